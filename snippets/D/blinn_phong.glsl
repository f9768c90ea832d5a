/* ---
id = "D.blinn_phong"
slot = "D"
summary = "Normalised Blinn-Phong normal distribution, exponent matched to Beckmann"
provides = ["distribution"]
requires = ["PI", "blinnPhongExponent", "cosinePower"]
domain = { NoH = [0, 1], a = [0.002, 1] }
reference = "D_blinn_phong"
# Measured on the GPU probe (llvmpipe): 0.8% at the peak for a = 0.002, where pow amplifies
# the error of log2(NoH) by n = 5·10⁵.
error_budget = { max_abs = 1.2e3, max_rel = 0.015 }
budget_why = "pow(NoH, n) with n = 2/a² − 2 ≈ 5·10⁵ at a = 0.002 amplifies the rounding of log2(NoH): measured 0.80 % relative, 599 absolute at the 8e4 peak on llvmpipe; the budget allows about 2x that."
sources = ["Blinn 1977", "Walter et al. 2007, section 5.2 (n = 2/a² − 2)", "lighting-model skill, Blinn-Phong"]
formula = 'D(\mathbf{h}) = \frac{n + 2}{2\pi} (\mathbf{n} \cdot \mathbf{h})^n, \quad n = \frac{2}{\alpha^2} - 2, \quad \alpha = \text{roughness}^2'
--- */
// D(h) = (n + 2) / (2π) NoHⁿ with n = 2/a² − 2: the (n + 2)/(2π) makes ∫ D (n·h) dω = 1, and
// this n gives the lobe of Beckmann with the same a (Walter et al. 2007). Takes a = roughness².
// pow at n up to 5·10⁵ amplifies the error of log2(NoH): the relative error grows as a → 0.
float distribution(float NoH, float a) {
    float n = blinnPhongExponent(a);
    return (n + 2.0) * (0.5 / PI) * cosinePower(NoH, n);
}
