/* ---
id = "specular.phong"
slot = "specular"
summary = "Classic Phong: F · (R·V)^(n/4), unnormalised, no cosine factor"
provides = ["specular"]
requires = ["Surface", "Dots", "blinnPhongExponent", "cosinePower"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0.2, 1] }
reference = "specular_phong"
error_budget = { max_abs = 1e-4, max_rel = 2e-4 }
budget_why = "pow(R·V, n/4) at roughness 0.2 (exponent 312): measured 3.0e-5 relative and 2.2e-5 absolute at the peak on llvmpipe; the budget leaves about 7x and 5x."
sources = ["Phong 1975", "lighting-model skill, variant 1 (classic Phong)", "Lighting models (Unity HLSL), 3. Phong"]
formula = 'f_s\,(\mathbf{n} \cdot \mathbf{l}) = F \max(\mathbf{r} \cdot \mathbf{v}, 0)^{n/4} \ \text{where}\ \mathbf{n} \cdot \mathbf{l} > 0, \quad \mathbf{r} \cdot \mathbf{v} = 2 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v}) - \mathbf{l} \cdot \mathbf{v}, \quad n = \frac{2}{\alpha^2} - 2, \quad \alpha = \text{roughness}^2'
--- */
// R is L mirrored about N, and R·V = 2(N·L)(N·V) − L·V needs no vector. The exponent is a
// quarter of the Blinn-Phong one: the lobe around R is about four times narrower in angle than
// the lobe of N·H for the same exponent (Fisher and Woo 1994). F stands in for the specular
// colour. Not normalised: highlights dim as roughness drops, and the lobe ignores energy.
vec3 specular(Surface s, Dots d, vec3 F) {
    if (d.NoLsigned <= 0.0) return vec3(0.0);
    float RoV = 2.0 * d.NoLsigned * d.NoV - d.LoV;
    return F * cosinePower(RoV, 0.25 * blinnPhongExponent(s.a));
}
