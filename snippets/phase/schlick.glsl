/* ---
id = "phase.schlick"
slot = "phase"
summary = "Schlick's rational stand-in for Henyey-Greenstein, k = 1.55g − 0.55g³ (no pow)"
provides = ["phase", "PHASE_MAX_K"]
requires = ["PI"]
domain = { cosTheta = [-1, 1], g = [-0.9, 0.9] }
reference = "phase_henyey_greenstein"
error_budget = { max_abs = 12.0, max_rel = 0.9 }
budget_why = "Schlick's stand-in parts from Henyey-Greenstein for strong scattering: at |g| = 0.9 it peaks at 26.7 where HG peaks at 15.1, measured 11.5 off (89 % relative); the budget is that design error."
sources = [
    "Blasi, Le Saec and Schlick 1993, A Rendering Algorithm for Discrete Volume Density Objects",
    "Pharr, Jakob and Humphreys, PBRT 3rd ed., 11.3.1 (the k(g) fit)",
]
formula = 'p(\theta) = \frac{1 - k^2}{4\pi \left( 1 - k \cos\theta \right)^2}, \quad k = \operatorname{clamp}(1.55\, g - 0.55\, g^3, -0.999, 0.999)'
--- */
// p = (1 − k²) / (4π (1 − k cosθ)²): normalised for any |k| < 1, and shaped like HG of the
// same asymmetry when k = 1.55g − 0.55g³. It is exactly isotropic at g = 0; the shapes part
// for strong forward scattering: at g = 0.9 Schlick peaks at 26.7 where HG peaks at 15.1.
// k(g) goes past 1 for g above 0.94 (it peaks at 1.0015), so k is clamped to keep the result
// finite and non-negative; the forward peak at the clamp is (1 + k)/(4π(1 − k)) ≈ 159.
#define PHASE_MAX_K 0.999

float phase(float cosTheta, float g) {
    float k = clamp(1.55 * g - 0.55 * g * g * g, -PHASE_MAX_K, PHASE_MAX_K);
    float d = 1.0 - k * cosTheta;
    return (0.25 / PI) * (1.0 - k) * (1.0 + k) / (d * d);
}
