/* ---
id = "phase.isotropic"
slot = "phase"
summary = "Isotropic scattering, 1/4π in every direction (Henyey-Greenstein at g = 0; g is ignored)"
provides = ["phase"]
requires = ["PI"]
domain = { cosTheta = [-1, 1], g = [0, 0] }
reference = "phase_henyey_greenstein"
error_budget = { max_abs = 1e-8 }
budget_why = "A constant 1/(4π) ≈ 0.0796: its only error is that constant rounded to float32, measured 3.2e-9; the budget is about 3x."
sources = ["Pharr, Jakob and Humphreys, PBRT 3rd ed., 11.2 (phase functions)"]
formula = 'p(\theta) = \frac{1}{4\pi}'
--- */

float phase(float cosTheta, float g) {
    return 0.25 / PI;
}
