/* ---
id = "diffuse.lambert"
slot = "diffuse"
summary = "Lambert: albedo / π times N·L (energy conserving)"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_lambert"
error_budget = { max_abs = 1e-6 }
budget_why = "A loose round bound: float32 rounding measured 1.3e-8 absolute on llvmpipe for values up to 1/π; 1e-6 is the common bound of the Lambert family, about 30 float32 ulps of 1/π."
sources = ["lighting-model skill, step 2"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} \max(\mathbf{n} \cdot \mathbf{l}, 0)'
--- */
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * (d.NoL / PI);
}
