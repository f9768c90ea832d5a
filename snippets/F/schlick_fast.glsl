/* ---
id = "F.schlick_fast"
slot = "F"
summary = "Schlick's Fresnel approximation with multiplies instead of pow"
provides = ["fresnel"]
requires = []
domain = { f0 = [0.02, 0.2], cosTheta = [0, 1] }
reference = "F_dielectric"
error_budget = { max_abs = 0.1, max_rel = 0.25 }
budget_why = "Same curve as F.schlick: it departs from the exact dielectric Fresnel by up to 0.092 (23.5 % relative) at f0 = 0.2, cosθ ≈ 0.11 (measured); the budget is that design error, not rounding."
sources = ["Schlick 1994", "Filament, shaders/src/brdf.fs, F_Schlick (pow5)"]
formula = 'F(\theta) = F_0 + (1 - F_0)\,x^2 x^2 x, \quad x = 1 - \cos\theta'
--- */
// Schlick's F with x⁵ as x²·x²·x: three multiplies, where pow is exp2(5 log2 x) and undefined
// at x < 0. Same error against the exact dielectric as F.schlick (0.036 at f0 = 0.04).
vec3 fresnel(vec3 f0, float cosTheta) {
    float x = clamp(1.0 - cosTheta, 0.0, 1.0);
    float x2 = x * x;
    return f0 + (1.0 - f0) * (x2 * x2 * x);
}
