/* ---
id = "diffuse.wrapped"
slot = "diffuse"
summary = "Wrapped Lambert, energy conserving: max(N·L + w, 0) / (1 + w)² / π"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
params = { DIFFUSE_WRAP = { type = "float", default = 0.5, range = [0.0, 1.0] } }
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_wrapped"
error_budget = { max_abs = 1e-6 }
budget_why = "A loose round bound: float32 rounding measured 9.7e-9 absolute on llvmpipe at the default wrap; 1e-6 is the common bound of the Lambert family, about 30 float32 ulps of 1/π."
sources = ["Filament PBR notes, 4.9.3 (wrap diffuse for cloth and subsurface)", "glsl brdf notes (Lambertian wrapped)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} \frac{\max(\mathbf{n} \cdot \mathbf{l} + w, 0)}{(1 + w)^2}, \quad w = \text{DIFFUSE\_WRAP}'
--- */
// Light reaches DIFFUSE_WRAP past the terminator, a cheap stand-in for light scattered under
// the surface. Dividing by (1 + w)² keeps the energy: over all light directions
// ∫ max(cosθ + w, 0) dω = π (1 + w)², so uniform light is reflected exactly as Lambert does.
vec3 diffuse(Surface s, Dots d) {
    float wrapped = max(d.NoLsigned + DIFFUSE_WRAP, 0.0);
    float norm = (1.0 + DIFFUSE_WRAP) * (1.0 + DIFFUSE_WRAP);
    return s.diffuseColor * (wrapped / (norm * PI));
}
