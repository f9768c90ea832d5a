/* ---
id = "D.blinn_phong"
slot = "D"
summary = "Normalised Blinn-Phong normal distribution, exponent matched to Beckmann"
provides = ["distribution", "MIN_BLINN_PHONG_A"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0.002, 1] }
reference = "D_blinn_phong"
# Measured on the GPU probe (llvmpipe): 0.8% at the peak for a = 0.002, where pow amplifies
# the error of log2(NoH) by n = 5·10⁵.
error_budget = { max_abs = 1.2e3, max_rel = 0.015 }
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
    // pow(0, 0) is undefined in GLSL (llvmpipe gives 0); at a = 1 the lobe is uniform, 0^0 = 1.
    float lobe = NoH > 0.0 ? pow(NoH, n) : (n > 0.0 ? 0.0 : 1.0);
    return (n + 2.0) * (0.5 / PI) * lobe;
}
