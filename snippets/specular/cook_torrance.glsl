/* ---
id = "specular.cook_torrance"
slot = "specular"
summary = "Cook-Torrance microfacet lobe assembled from the chosen D, F and V"
provides = ["specular"]
requires = ["Surface", "Dots", "D", "V"]
sources = ["lighting-model skill, step 7", "Cook and Torrance 1982"]
formula = 'f_s\,(\mathbf{n} \cdot \mathbf{l}) = D(\mathbf{h})\, V\, F\, (\mathbf{n} \cdot \mathbf{l}) = \frac{D\, G\, F}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})} (\mathbf{n} \cdot \mathbf{l})'
--- */
// V already holds G / (4 NoL NoV), so the lobe is a plain product, times its cosine N·L.
vec3 specular(Surface s, Dots d, vec3 F) {
    return distribution(d.NoH, s.a) * visibility(d, s.a) * F * d.NoL;
}
