/* ---
id = "diffuse.oren_nayar_qualitative"
slot = "diffuse"
summary = "Oren-Nayar, qualitative model: A + B·max(0, cos φ)·sin α·tan β, no interreflection"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0, 1] }
reference = "diffuse_oren_nayar"
# Against the full model: it drops the C3 and interreflection terms, so the error grows with
# roughness (measured on llvmpipe: max abs 0.056, at roughness 1 and grazing N·V).
error_budget = { max_abs = 0.06 }
budget_why = "It drops the full model's C3 and interreflection terms, so its error grows with roughness: measured 0.056 at roughness 1 and grazing N·V; the budget is that design error, not rounding."
sources = ["Oren and Nayar 1994, eq. 30 (qualitative model)", "Lighting models (Unity HLSL), 7. Oren-Nayar"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} (\mathbf{n} \cdot \mathbf{l}) \left( A + B \frac{\max\left( 0,\ \mathbf{l} \cdot \mathbf{v} - (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v}) \right)}{\max(\mathbf{n} \cdot \mathbf{l}, \mathbf{n} \cdot \mathbf{v})} \right), \quad A = 1 - \frac{0.5\sigma^2}{\sigma^2 + 0.33}, \quad B = \frac{0.45\sigma^2}{\sigma^2 + 0.09}, \quad \sigma = \text{roughness}'
--- */
// max(0, cos φ)·sin α·tan β with α, β the larger and smaller of the two polar angles. Since
// sin α·sin β = sin θl·sin θv and cos φ·sin θl·sin θv = L·V − (N·L)(N·V), the product is
// max(0, L·V − N·L·N·V) / max(N·L, N·V): no acos, no tan, no division by the sines.
vec3 diffuse(Surface s, Dots d) {
    float s2 = s.diffuseRoughness * s.diffuseRoughness;
    float A = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float B = 0.45 * s2 / (s2 + 0.09);
    float azimuth = max(d.LoV - d.NoL * d.NoV, 0.0);
    float term = azimuth / max(max(d.NoL, d.NoV), 1e-4);
    return s.diffuseColor * ((A + B * term) * d.NoL / PI);
}
