/* ---
id = "V.smith_ggx_correlated_fast"
slot = "V"
summary = "Hammon's linear approximation of height-correlated Smith GGX visibility"
provides = ["visibility", "MIN_VIS_FAST_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_ggx_correlated"
error_budget = { max_abs = 600.0, max_rel = 0.3 }
budget_why = "Hammon's line in a in place of the square roots is an approximation: measured off by 365 of 2451 at NoL = NoV = 0.01, a = 0.002, and up to 27 % relative; the budget is that design error (1.6x and 1.1x)."
sources = ["Hammon 2017, PBR Diffuse Lighting for GGX+Smith Microsurfaces (GDC)", "Heitz 2014"]
formula = 'V = \frac{0.5}{(1 - \alpha)\, 2 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v}) + \alpha\, (\mathbf{n} \cdot \mathbf{l} + \mathbf{n} \cdot \mathbf{v})}, \quad \alpha = \text{roughness}^2'
--- */
// Smallest denominator: it vanishes when NoL = NoV = 0.
#define MIN_VIS_FAST_DENOM 1e-5

// V ≈ 0.5 / mix(2 NoL NoV, NoL + NoV, a): the square roots of the exact form replaced by a
// line in a (Hammon 2017). Exact at a = 0 and a = 1; its error peaks at mid roughness.
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    return 0.5 / max(mix(2.0 * NoL * NoV, NoL + NoV, a), MIN_VIS_FAST_DENOM);
}
