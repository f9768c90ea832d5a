/* ---
id = "specular.cook_torrance"
slot = "specular"
summary = "Cook-Torrance microfacet lobe assembled from the chosen D, F and V"
provides = ["specular"]
requires = ["Surface", "Dots", "D", "V"]
# Measured as the balanced tier composes it (D.ggx, V.smith_ggx_correlated), against the
# product of those terms' float64 references: the lobe's own arithmetic on top of its terms'.
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0.05, 1] }
reference = "specular_cook_torrance_ggx"
error_budget = { max_abs = 400.0, max_rel = 0.03 }
budget_why = "The lobe inherits D.ggx's float32 cancellation next to N·H = 1: measured 1.9 % relative (233 on a peak of 1.25e4) at roughness 0.05, N·L = N·V = 1 on llvmpipe; the budget is D.ggx's 3 % at that peak."
sources = ["lighting-model skill, step 7", "Cook and Torrance 1982"]
formula = 'f_s\,(\mathbf{n} \cdot \mathbf{l}) = D(\mathbf{h})\, V\, F\, (\mathbf{n} \cdot \mathbf{l}) = \frac{D\, G\, F}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})} (\mathbf{n} \cdot \mathbf{l})'
--- */
// V already holds G / (4 NoL NoV), so the lobe is a plain product, times its cosine N·L.
vec3 specular(Surface s, Dots d, vec3 F) {
    return distribution(d.NoH, s.a) * visibility(d, s.a) * F * d.NoL;
}
