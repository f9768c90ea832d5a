/* ---
id = "phase.henyey_greenstein"
slot = "phase"
summary = "Henyey-Greenstein phase function, g clamped to [-0.99, 0.99] (peak (1+g)/(4π(1−g)²) ≈ 1583.6 there)"
provides = ["phase", "PHASE_MAX_G"]
requires = ["PI"]
domain = { cosTheta = [-1, 1], g = [-0.99, 0.99] }
reference = "phase_henyey_greenstein"
error_budget = { max_abs = 5e-4, max_rel = 1e-6 }
budget_why = "Written without the cancellation at the peak: measured 2.9e-7 relative and 1.8e-4 absolute next to the 1583.6 peak (g = −0.99, straight back) on llvmpipe; the budget leaves about 3x."
sources = [
    "lighting-model skill, common variants (SSS: Henyey-Greenstein)",
    "Henyey and Greenstein 1941, Diffuse radiation in the galaxy",
]
formula = 'p(\theta) = \frac{1 - g^2}{4\pi \left( 1 + g^2 - 2 g \cos\theta \right)^{3/2}}, \quad g \in [-0.99, 0.99]'
--- */
// cosTheta is the cosine of the scattering angle, between the light's direction of travel and
// the scattered direction (for light from L seen from V: −dot(L, V)); g > 0 scatters forward.
// |g| → 1 is a Dirac spike: the clamp keeps the peak finite, (1 + g)/(4π(1 − g)²) ≈ 1583.6 at
// g = 0.99, and (1 − g)/(4π(1 + g)²) ≈ 2.0e-4 straight back.
#define PHASE_MAX_G 0.99

// p = (1 − g²) / (4π (1 + g² − 2g cosθ)^1.5). The denominator is written
// (1 − |g|)² + 2|g|(1 − sign(g) cosθ): the same value, without the cancellation of
// 1 + g² − 2g cosθ at the peak (g → ±1, cosθ = sign g), where it is tiny and everything rides
// on it; 1 − cosθ is exact in float for cosθ in [0.5, 1] (Sterbenz).
float phase(float cosTheta, float g) {
    float gc = clamp(g, -PHASE_MAX_G, PHASE_MAX_G);
    float ag = abs(gc);
    float d = (1.0 - ag) * (1.0 - ag) + 2.0 * ag * (1.0 - sign(gc) * cosTheta);
    return (0.25 / PI) * (1.0 - ag) * (1.0 + ag) / (d * sqrt(d));
}
