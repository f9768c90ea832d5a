/* ---
id = "D.ggx"
slot = "D"
summary = "GGX / Trowbridge-Reitz normal distribution"
provides = ["distribution", "MIN_GGX_DENOM"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0.002, 1] }
reference = "D_ggx"
error_budget = { max_abs = 2.5e3, max_rel = 0.03 }
budget_why = "D peaks at 1/(π a²) ≈ 8e4 at a = 0.002, where h²(a² − 1) + 1 cancels in float32: rounding analysis gives up to ~3 %, i.e. 2.5e3 at the peak. Measured on llvmpipe only 6.1e-7; unfused float32 on the bench grid, 0.35 %."
sources = ["lighting-model skill, step 5", "Walter et al. 2007, eq. 33"]
formula = 'D(\mathbf{h}) = \frac{\alpha^2}{\pi \left( (\mathbf{n} \cdot \mathbf{h})^2 (\alpha^2 - 1) + 1 \right)^2}, \quad \alpha = \text{roughness}^2'
--- */
// Floor of (NoH² (a² − 1) + 1): it is 0 at a = 0, NoH = 1, where D is a Dirac spike (0/0).
#define MIN_GGX_DENOM 1e-15

// D(h) = a² / (π ((n·h)² (a² − 1) + 1)²). Takes a = roughness², never roughness.
// In float32 the denominator loses digits by cancellation next to NoH = 1 at low roughness
// (about 3% at a = 0.002); D.ggx_mediump avoids it.
float distribution(float NoH, float a) {
    float h = clamp(NoH, 0.0, 1.0);
    float a2 = a * a;
    float d = max(h * h * (a2 - 1.0) + 1.0, MIN_GGX_DENOM);
    return a2 / (PI * d * d);
}
