/* ---
id = "V.smith_ggx_correlated"
slot = "V"
summary = "Height-correlated Smith visibility for GGX, G / (4 NoL NoV), exact form"
provides = ["visibility", "MIN_VIS_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_ggx_correlated"
error_budget = { max_abs = 2e-3, max_rel = 1e-5 }
budget_why = "The exact form, float32 rounding only: measured 1.6e-7 relative and 1.9e-4 absolute where V is 2451 (NoL = NoV = 0.01, a = 0.002) on llvmpipe; the budget leaves about 60x and 10x."
sources = ["lighting-model skill, step 6 method 2", "Heitz 2014, eq. 99", "Filament PBR notes 4.4.2"]
formula = 'V = \frac{0.5}{(\mathbf{n} \cdot \mathbf{l}) \sqrt{(\mathbf{n} \cdot \mathbf{v})^2 (1 - \alpha^2) + \alpha^2} + (\mathbf{n} \cdot \mathbf{v}) \sqrt{(\mathbf{n} \cdot \mathbf{l})^2 (1 - \alpha^2) + \alpha^2}}'
--- */
// Smallest denominator: both terms vanish when NoL = NoV = 0.
#define MIN_VIS_DENOM 1e-5

// V = G2 / (4 NoL NoV) with G2 = 1 / (1 + Λ(v) + Λ(l)), Λ of GGX, multiplied out so that it is
// finite at NoL = 0 (Heitz 2014, Filament). The cosines are clamped to [0, 1].
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    float a2 = a * a;
    float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, MIN_VIS_DENOM);
}
