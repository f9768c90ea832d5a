/* ---
id = "diffuse.half_lambert"
slot = "diffuse"
summary = "Valve's half-Lambert ((N·L + 1)/2)² / π: no dark terminator, 4/3 of the energy"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_half_lambert"
error_budget = { max_abs = 1e-6 }
budget_why = "A loose round bound: float32 rounding measured 2.2e-8 absolute on llvmpipe; 1e-6 is the common bound of the Lambert family, about 30 float32 ulps of 1/π."
sources = ["kchapelier, lighting technique notes (Half Lambert)", "Valve Developer Wiki, Half Lambert", "lighting-model skill, step 2"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} \left( \frac{\mathbf{n} \cdot \mathbf{l} + 1}{2} \right)^2'
--- */
// Remaps N·L from [-1, 1] to [0, 1] and squares it, so the side facing away from the light is
// still shaded instead of flat black. Lights everything, even from behind: under uniform light
// it reflects 4/3 of what arrives (a stylised model, not an energy-conserving one).
vec3 diffuse(Surface s, Dots d) {
    float wrapped = 0.5 * d.NoLsigned + 0.5;
    return s.diffuseColor * (wrapped * wrapped / PI);
}
