/* ---
id = "V.schlick_ggx_remapped"
slot = "V"
summary = "Separable Schlick-GGX visibility with UE4's remap for analytic lights, k = (r+1)²/8"
provides = ["visibility", "MIN_SCHLICK_G1_REMAPPED_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_ggx_separable_remapped"
error_budget = { max_abs = 2.0, max_rel = 0.26 }
budget_why = "Schlick's G1 against separable Smith GGX at the remapped roughness is a fit: measured off by up to 1.66 (at NoL = NoV ≈ 0.06, a = 0.002) and 25.8 % relative; the budget is that design error."
sources = ["Karis 2013, Real Shading in Unreal Engine 4, p. 3", "lighting-model skill, step 6 method 1"]
formula = 'V = \frac{G_1(\mathbf{n} \cdot \mathbf{l})\, G_1(\mathbf{n} \cdot \mathbf{v})}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})}, \quad G_1(x) = \frac{x}{x (1 - k) + k}, \quad k = \frac{(\sqrt{\alpha} + 1)^2}{8} = \frac{(\text{roughness} + 1)^2}{8}'
--- */
// Smallest Schlick G1 denominator; with this k it never falls below 1/8, kept for symmetry.
#define MIN_SCHLICK_G1_REMAPPED_DENOM 1e-5

// Schlick's G1 with k = (r + 1)²/8, r = √a the perceptual roughness: Karis's remap of
// roughness to (r + 1)/2 for analytic lights, which tames the hot rims of smooth surfaces.
// It approximates separable Smith GGX at a' = ((r + 1)/2)², not at a.
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    float r = sqrt(max(a, 0.0)) + 1.0;
    float k = r * r * 0.125;
    float gl = max(NoL * (1.0 - k) + k, MIN_SCHLICK_G1_REMAPPED_DENOM);
    float gv = max(NoV * (1.0 - k) + k, MIN_SCHLICK_G1_REMAPPED_DENOM);
    return 0.25 / (gl * gv);
}
