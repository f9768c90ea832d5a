/* ---
id = "V.schlick_ggx"
slot = "V"
summary = "Separable Schlick-GGX visibility, k = a/2"
provides = ["visibility", "MIN_SCHLICK_G1_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_ggx_separable"
error_budget = { max_abs = 700.0, max_rel = 0.36 }
budget_why = "Schlick's G1 with k = a/2 fits Smith GGX's G1 but is not it: measured off by 381 of 2451 at NoL = NoV = 0.01, a = 0.002, and up to 32 % relative; the budget is that design error (about 1.8x and 1.1x)."
sources = ["Schlick 1994", "Karis 2013, Real Shading in Unreal Engine 4, p. 3", "lighting-model skill, step 6 method 1"]
formula = 'V = \frac{G_1(\mathbf{n} \cdot \mathbf{l})\, G_1(\mathbf{n} \cdot \mathbf{v})}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})}, \quad G_1(x) = \frac{x}{x (1 - k) + k}, \quad k = \frac{\alpha}{2}'
--- */
// Smallest Schlick G1 denominator NoX (1 − k) + k: it is 0 at NoX = 0 with a = 0.
#define MIN_SCHLICK_G1_DENOM 1e-5

// Schlick's G1(x) = x / (x (1 − k) + k) with k = a/2, which fits Smith GGX's G1 (Karis 2013).
// V = G1(l) G1(v) / (4 NoL NoV): the NoL NoV of the numerators cancel, so V is finite at
// NoL = 0 without a special case.
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    float k = 0.5 * a;
    float gl = max(NoL * (1.0 - k) + k, MIN_SCHLICK_G1_DENOM);
    float gv = max(NoV * (1.0 - k) + k, MIN_SCHLICK_G1_DENOM);
    return 0.25 / (gl * gv);
}
