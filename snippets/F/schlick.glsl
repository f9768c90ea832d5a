/* ---
id = "F.schlick"
slot = "F"
summary = "Schlick's Fresnel approximation with pow"
provides = ["fresnel"]
requires = []
domain = { f0 = [0.02, 0.2], cosTheta = [0, 1] }
reference = "F_dielectric"
error_budget = { max_abs = 0.1, max_rel = 0.25 }
budget_why = "Schlick's curve departs from the exact dielectric Fresnel by up to 0.092 (23.5 % relative) at f0 = 0.2, cosθ ≈ 0.11 (measured; 0.036 at f0 = 0.04); the budget is that design error, not rounding."
sources = ["lighting-model skill, step 4", "Schlick 1994"]
formula = 'F(\theta) = F_0 + (1 - F_0)\,(1 - \cos\theta)^5'
--- */
// F = f0 + (1 − f0)(1 − cosθ)⁵ (Schlick 1994), an approximation of the exact dielectric
// Fresnel: within 0.036 of it at f0 = 0.04, 0.10 at f0 = 0.2 (the budget's domain is
// dielectrics, water to diamond; towards f0 = 1 the exact dielectric has a Brewster dip that
// Schlick lacks). cosTheta is V·H for a light, N·V for the environment; never N·L.
// 1 − cosTheta is clamped: pow of a negative base is undefined in GLSL.
vec3 fresnel(vec3 f0, float cosTheta) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}
