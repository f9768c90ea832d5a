/* ---
id = "F.schlick_f90"
slot = "F"
summary = "Schlick's Fresnel with f90 derived from f0 (pre-baked specular occlusion)"
provides = ["fresnel", "F90_FROM_F0"]
requires = []
domain = { f0 = [0.02, 0.2], cosTheta = [0, 1] }
reference = "F_dielectric"
error_budget = { max_abs = 0.1, max_rel = 0.25 }
budget_why = "For f0 ≥ 0.02 f90 is 1 and this is Schlick's curve, which departs from the exact dielectric Fresnel by up to 0.092 (23.5 % relative) at f0 = 0.2, cosθ ≈ 0.11 (measured); the budget is that design error."
sources = ["Filament PBR notes 4.4.3 and 4.8.3.3 (pre-baked occlusion)", "Schlick 1994"]
formula = 'F(\theta) = F_0 + (F_{90} - F_0)\,(1 - \cos\theta)^5, \quad F_{90} = \min\left( 1,\ 16.5\,(F_{0,r} + F_{0,g} + F_{0,b}) \right)'
--- */
// Scale from f0 to f90: a reflectance below 2% is taken as no specular at all, so grazing
// reflection fades with it (Filament: f90 = saturate(dot(f0, vec3(50 · 0.33)))).
#define F90_FROM_F0 (50.0 * 0.33)

// F = f0 + (f90 − f0)(1 − cosθ)⁵. For f0 ≥ 0.02 f90 is 1 and this is F.schlick; below, it
// departs from the dielectric on purpose (occluded cavities), so the budget's domain starts
// at 0.02.
vec3 fresnel(vec3 f0, float cosTheta) {
    float f90 = clamp(dot(f0, vec3(F90_FROM_F0)), 0.0, 1.0);
    float x = clamp(1.0 - cosTheta, 0.0, 1.0);
    float x2 = x * x;
    return f0 + (f90 - f0) * (x2 * x2 * x);
}
