/* ---
id = "D.blinn_phong"
slot = "D"
summary = "Normalised Blinn-Phong normal distribution, exponent matched to Beckmann"
provides = ["distribution", "MIN_BLINN_PHONG_A"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0.002, 1] }
reference = "D_blinn_phong"
error_budget = { max_abs = 0.05, max_rel = 1e-3 }
sources = ["Blinn 1977", "Walter et al. 2007, section 5.2 (n = 2/a² − 2)", "lighting-model skill, Blinn-Phong"]
--- */
// Smallest a: 2/a² is the exponent, and at a = 0 pow(1, ∞) is undefined.
#define MIN_BLINN_PHONG_A 1e-3

// D(h) = (n + 2) / (2π) NoHⁿ with n = 2/a² − 2: the (n + 2)/(2π) makes ∫ D (n·h) dω = 1, and
// this n gives the lobe of Beckmann with the same a (Walter et al. 2007). Takes a = roughness².
// pow at n up to 5·10⁵ amplifies the error of log2(NoH): the relative error grows as a → 0.
float distribution(float NoH, float a) {
    NoH = clamp(NoH, 0.0, 1.0);
    float aSafe = max(a, MIN_BLINN_PHONG_A);
    float n = 2.0 / (aSafe * aSafe) - 2.0;
    return (n + 2.0) * (0.5 / PI) * pow(NoH, n);
}
