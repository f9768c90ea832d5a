/* ---
id = "D.beckmann"
slot = "D"
summary = "Beckmann normal distribution"
provides = ["distribution", "MIN_BECKMANN_DENOM"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0.002, 1] }
reference = "D_beckmann"
error_budget = { max_abs = 0.05, max_rel = 1e-4 }
budget_why = "Float32 rounding only: measured 2.6e-6 relative and 0.010 absolute at the 8e4 peak (a = 0.002, NoH → 1) on llvmpipe; the budget leaves about 40x and 5x for drivers with looser exp."
sources = ["Beckmann & Spizzichino 1963", "Walter et al. 2007, eq. 25", "BRDF functions page (seed 004)"]
formula = 'D(\mathbf{h}) = \frac{1}{\pi \alpha^2 (\mathbf{n} \cdot \mathbf{h})^4} \exp\left( \frac{(\mathbf{n} \cdot \mathbf{h})^2 - 1}{\alpha^2 (\mathbf{n} \cdot \mathbf{h})^2} \right), \quad \alpha = \text{roughness}^2'
--- */
// Floor of π a² NoH⁴: it is 0 at grazing (NoH = 0) and for a mirror (a = 0).
#define MIN_BECKMANN_DENOM 1e-30

// D(h) = exp(−tan²θ / a²) / (π a² cos⁴θ), tan²θ = (1 − NoH²) / NoH². Takes a = roughness².
// The exponent is written (NoH² − 1) / (a² NoH²) with (1 − NoH)(1 + NoH), exact near NoH = 1.
float distribution(float NoH, float a) {
    float h = clamp(NoH, 0.0, 1.0);
    float NoH2 = h * h;
    float a2NoH2 = max(a * a * NoH2, MIN_BECKMANN_DENOM);
    float e = exp(-(1.0 - h) * (1.0 + h) / a2NoH2);
    return e / max(PI * a2NoH2 * NoH2, MIN_BECKMANN_DENOM);
}
