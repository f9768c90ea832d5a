/* ---
id = "diffuse.oren_nayar_improved"
slot = "diffuse"
summary = "Fujii's improved Oren-Nayar: ρ(A + B·s/t) without acos or tan, energy-balanced A"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0, 1] }
reference = "diffuse_oren_nayar"
# Against the full model, a different fit read with the same σ (measured on llvmpipe: max abs
# 0.12, at roughness 1 and grazing N·V, where it is about half the full model).
error_budget = { max_abs = 0.13 }
budget_why = "Fujii's fit is a different model read with the same σ: against the full Oren-Nayar it is off by up to 0.12 (measured, roughness 1 and grazing N·V, where it is about half the full model); the budget is that design error."
sources = ["Fujii 2012, A tiny improvement of Oren-Nayar reflectance model", "kchapelier, lighting technique notes (Oren Nayar)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \rho\, (\mathbf{n} \cdot \mathbf{l}) \left( A + B \frac{s}{t} \right), \quad s = \mathbf{l} \cdot \mathbf{v} - (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v}), \quad t = \begin{cases} \max(\mathbf{n} \cdot \mathbf{l}, \mathbf{n} \cdot \mathbf{v}) & s > 0 \\ 1 & s \le 0 \end{cases}, \quad A = \frac{1}{\pi + \left( \frac{\pi}{2} - \frac{2}{3} \right) \sigma}, \quad B = \sigma A, \quad \sigma = \text{roughness}'
--- */
// s = L·V − (N·L)(N·V) is cos φ·sin θl·sin θv; t = max(N·L, N·V) where s > 0, else 1, so that
// s/t is the qualitative model's cos φ·sin α·tan β when the azimuth term is positive and
// stays bounded when it is negative. A and B are chosen so that σ = 0 is Lambert and the
// albedo stays near 1 for every σ (Fujii 2012).
vec3 diffuse(Surface s, Dots d) {
    float sigma = s.diffuseRoughness;
    float A = 1.0 / (PI + (0.5 * PI - 2.0 / 3.0) * sigma);
    float B = sigma * A;
    float sTerm = d.LoV - d.NoL * d.NoV;
    float t = sTerm > 0.0 ? max(max(d.NoL, d.NoV), 1e-4) : 1.0;
    return s.diffuseColor * ((A + B * sTerm / t) * d.NoL);
}
