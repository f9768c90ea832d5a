/* ---
id = "diffuse.generalized"
slot = "diffuse"
summary = "Generalized Lambert: max(N·L · multiply + add, 0)^power / π"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
params = { LAMBERT_MULTIPLY = { type = "float", default = 1.0, range = [0.0, 2.0] }, LAMBERT_ADD = { type = "float", default = 0.0, range = [-1.0, 1.0] }, LAMBERT_POWER = { type = "float", default = 1.0, range = [0.1, 8.0] } }
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_generalized"
error_budget = { max_abs = 1e-6 }
budget_why = "A loose round bound: float32 rounding measured 1.3e-8 absolute at the defaults (Lambert, values up to 1/π) on llvmpipe; 1e-6 is the common bound of the Lambert family, about 30 float32 ulps of 1/π."
sources = ["kchapelier, lighting technique notes (Generalized Lambert)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} \max\left( m\,(\mathbf{n} \cdot \mathbf{l}) + b,\ 0 \right)^p, \quad m = \text{LAMBERT\_MULTIPLY}, \quad b = \text{LAMBERT\_ADD}, \quad p = \text{LAMBERT\_POWER}'
--- */
// One family for the Lambert look-alikes: (1, 0, 1) is Lambert, (0.5, 0.5, 1) the skill's
// half-Lambert, (0.5, 0.5, 2) Valve's. Only the first conserves energy.
vec3 diffuse(Surface s, Dots d) {
    float x = max(d.NoLsigned * LAMBERT_MULTIPLY + LAMBERT_ADD, 0.0);
    // pow(0, y) is undefined in GLSL for y <= 0; LAMBERT_POWER's range keeps y > 0.
    return s.diffuseColor * (pow(x, LAMBERT_POWER) / PI);
}
