/* ---
id = "V.g1v"
slot = "V"
summary = "Hable's G1V visibility: Schlick-GGX with k = a/2, normalised as G / (4 NoL NoV)"
provides = ["visibility", "MIN_G1V_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_ggx_separable"
error_budget = { max_abs = 700.0, max_rel = 0.36 }
budget_why = "Schlick's G1 with k = a/2 fits Smith GGX's G1 but is not it: measured off by 381 of 2451 at NoL = NoV = 0.01, a = 0.002, and up to 32 % relative; the budget is that design error (about 1.8x and 1.1x)."
sources = ["Hable 2014, Optimizing GGX Shaders with dot(L,H) (seed 004)", "lighting-model skill, step 6 method 3"]
formula = 'V = \frac{1}{4}\, G_{1V}(\mathbf{n} \cdot \mathbf{l})\, G_{1V}(\mathbf{n} \cdot \mathbf{v}), \quad G_{1V}(x) = \frac{1}{x (1 - k) + k}, \quad k = \frac{\alpha}{2}'
--- */
// Smallest G1V denominator NoX (1 − k) + k: it is 0 at NoX = 0 with a = 0.
#define MIN_G1V_DENOM 1e-5

// G1V(x) = 1 / (x (1 − k) + k) is Schlick's G1 divided by x, k = a/2. The seeds multiply
// G1V(NoL) G1V(NoV) straight into D F NoL: that is G / (NoL NoV) and lacks the 1/4 of the
// microfacet BRDF, so as a visibility it is quartered here. Same values as V.schlick_ggx,
// written as the seeds write it.
float visibility(Dots d, float a) {
    float k = 0.5 * a;
    float g1l = 1.0 / max(clamp(d.NoL, 0.0, 1.0) * (1.0 - k) + k, MIN_G1V_DENOM);
    float g1v = 1.0 / max(clamp(d.NoV, 0.0, 1.0) * (1.0 - k) + k, MIN_G1V_DENOM);
    return 0.25 * g1l * g1v;
}
