/* ---
id = "D.ggx_mediump"
slot = "D"
summary = "GGX normal distribution, written to survive half precision"
provides = ["distribution", "MIN_GGX_MEDIUMP_DENOM", "MEDIUMP_FLT_MAX"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0.0025, 1] }
reference = "D_ggx"
error_budget = { max_abs = 0.05, max_rel = 1e-5 }
budget_why = "Rearranged so nothing cancels next to NoH = 1: measured 3.4e-7 relative and 0.0073 absolute at the 5.1e4 peak (a = 0.0025) on llvmpipe float32; the budget leaves about 30x and 7x for other drivers."
sources = ["Filament, shaders/src/brdf.fs, D_GGX", "Filament PBR notes 4.4.1", "Walter et al. 2007"]
formula = 'D(\mathbf{h}) = \min\left( \frac{1}{\pi} \left( \frac{\alpha}{(1 - \mathbf{n} \cdot \mathbf{h})(1 + \mathbf{n} \cdot \mathbf{h}) + (\alpha\, \mathbf{n} \cdot \mathbf{h})^2} \right)^2,\ 65504 \right), \quad \alpha = \text{roughness}^2'
--- */
// Floor of the denominator: 0 at a = 0, NoH = 1, where D is a Dirac spike.
#define MIN_GGX_MEDIUMP_DENOM 1e-30
// Largest finite half float: D of a mirror-like surface exceeds it at the peak.
#define MEDIUMP_FLT_MAX 65504.0

// D(h) = (a / (sin²θ + (NoH a)²))² / π, the GGX of D.ggx rearranged as in Filament.
// 1 − NoH² in half precision is all rounding error next to NoH = 1 (Filament computes it as
// |N×H|², which this scalar signature cannot see), so it is taken as (1 − NoH)(1 + NoH):
// 1 − NoH is exact there (Sterbenz). The result is clamped to MEDIUMP_FLT_MAX so that it
// cannot overflow to infinity in mediump; below a ≈ 0.0022 the clamp cuts the peak.
float distribution(float NoH, float a) {
    float h = clamp(NoH, 0.0, 1.0);
    float oneMinusNoHSquared = (1.0 - h) * (1.0 + h);
    float aNoH = a * h;
    float k = a / max(oneMinusNoHSquared + aNoH * aNoH, MIN_GGX_MEDIUMP_DENOM);
    return min(k * k * (1.0 / PI), MEDIUMP_FLT_MAX);
}
