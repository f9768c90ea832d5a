/* ---
id = "V.smith_beckmann"
slot = "V"
summary = "Height-correlated Smith visibility for Beckmann, Walter's rational Λ"
provides = ["visibility", "cLambdaBeckmann", "MIN_BECKMANN_VIS_DENOM"]
requires = ["Dots"]
domain = { NoV = [0.01, 1], NoL = [0.01, 1], a = [0.002, 1] }
reference = "V_smith_beckmann_correlated"
error_budget = { max_abs = 15.0, max_rel = 0.01 }
budget_why = "Walter's rational Λ in place of erf is a fit: measured within 0.62 % of the exact form (2.7 of 787 at NoL = NoV = 0.01); the 1 % relative budget covers it, and 15 absolute is a loose bound for values up to 2500."
sources = ["Walter et al. 2007, eq. 27", "Heitz 2014, eq. 99"]
formula = 'V = \frac{1}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v}) \left( 1 + \Lambda(\mathbf{n} \cdot \mathbf{l}) + \Lambda(\mathbf{n} \cdot \mathbf{v}) \right)}, \quad \Lambda(c) = \begin{cases} \dfrac{1 - 1.259\mu + 0.396\mu^2}{3.535\mu + 2.181\mu^2} & \mu < 1.6 \\ 0 & \mu \ge 1.6 \end{cases}, \quad \mu = \frac{c}{\alpha \sqrt{1 - c^2}}'
--- */
// Smallest denominator: a sinθ for μ, and the whole of V's at NoL = NoV = 0.
#define MIN_BECKMANN_VIS_DENOM 1e-5

// c·Λ(c) for Beckmann, μ = c / (a sinθ): Walter's fit Λ ≈ (1 − 1.259μ + 0.396μ²) /
// (3.535μ + 2.181μ²) for μ < 1.6, else 0 (in place of erf). Multiplied by c = μ a sinθ it is
// finite at c = 0, where Λ itself is infinite.
float cLambdaBeckmann(float c, float a) {
    float s = sqrt(max((1.0 - c) * (1.0 + c), 0.0));
    float as = a * s;
    float mu = c / max(as, MIN_BECKMANN_VIS_DENOM);
    if (mu >= 1.6) {
        return 0.0;
    }
    return as * (1.0 - 1.259 * mu + 0.396 * mu * mu) / (3.535 + 2.181 * mu);
}

// V = G2 / (4 NoL NoV), G2 = 1 / (1 + Λ(v) + Λ(l)), written as
// 1 / (4 (NoL NoV + NoV·cΛ(NoL) + NoL·cΛ(NoV))) so that it is finite at NoL = 0.
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    float denom = NoL * NoV + NoV * cLambdaBeckmann(NoL, a) + NoL * cLambdaBeckmann(NoV, a);
    return 0.25 / max(denom, MIN_BECKMANN_VIS_DENOM);
}
