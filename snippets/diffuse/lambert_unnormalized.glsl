/* ---
id = "diffuse.lambert_unnormalized"
slot = "diffuse"
summary = "Lambert without 1/π: albedo · N·L, the form most ShaderToy code writes"
provides = ["diffuse"]
requires = ["Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_lambert_unnormalized"
error_budget = { max_abs = 1e-6 }
budget_why = "A loose round bound: albedo·N·L matched its reference exactly on llvmpipe (measured 0); 1e-6 is the common bound of the Lambert family, left for drivers that round differently."
sources = ["lighting-model skill, step 2", "kchapelier, lighting technique notes (Lambert)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \rho \max(\mathbf{n} \cdot \mathbf{l}, 0)'
--- */
// Reflects π times more than Lambert: a scene written for it has lights π times dimmer. Swapped
// into a scene lit for albedo/π it brightens everything by π.
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * d.NoL;
}
