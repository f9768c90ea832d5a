/* ---
id = "specular.blinn_phong"
slot = "specular"
summary = "Blinn-Phong, unnormalised: F · (N·H)^n, no cosine factor"
provides = ["specular"]
requires = ["Surface", "Dots", "blinnPhongExponent", "cosinePower"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0.2, 1] }
reference = "specular_blinn_phong"
error_budget = { max_abs = 2e-4, max_rel = 5e-4 }
budget_why = "pow(N·H, n) at roughness 0.2 (n = 1248) amplifies the rounding of log2(N·H): measured 1.2e-4 relative and 9.2e-5 absolute at the peak on llvmpipe; the budget is about 4x and 2x that."
sources = ["Blinn 1977", "lighting-model skill, step 3", "Lighting models (Unity HLSL), 4. Blinn-Phong"]
formula = 'f_s\,(\mathbf{n} \cdot \mathbf{l}) = F\, (\mathbf{n} \cdot \mathbf{h})^n \ \text{where}\ \mathbf{n} \cdot \mathbf{l} > 0, \quad n = \frac{2}{\alpha^2} - 2, \quad \alpha = \text{roughness}^2'
--- */
// The highlight's peak is F whatever the roughness, so smooth surfaces look dimmer than they
// should; pair it with lights tuned by eye, not with a physically based mix.
vec3 specular(Surface s, Dots d, vec3 F) {
    if (d.NoLsigned <= 0.0) return vec3(0.0);
    return F * cosinePower(d.NoH, blinnPhongExponent(s.a));
}
