/* ---
id = "core.shininess"
slot = "core"
summary = "Blinn-Phong exponent from a = roughness², and the cosine power lobe"
provides = ["blinnPhongExponent", "cosinePower", "MIN_BLINN_PHONG_A"]
requires = []
sources = ["Walter et al. 2007, Microfacet models for refraction, section 5.2"]
formula = 'n = \frac{2}{\max(\alpha, 10^{-3})^2} - 2, \quad \operatorname{cosinePower}(c, n) = \operatorname{clamp}(c, 0, 1)^n \ (\text{with } 0^0 = 1)'
--- */
// Smallest a: the exponent is 2/a², and at a = 0 pow(1, ∞) is undefined.
#define MIN_BLINN_PHONG_A 1e-3

// n = 2/a² − 2 gives the Blinn-Phong lobe the shape of Beckmann's with the same a; 0 at a = 1.
float blinnPhongExponent(float a) {
    float aSafe = max(a, MIN_BLINN_PHONG_A);
    return 2.0 / (aSafe * aSafe) - 2.0;
}

// cⁿ for a cosine c clamped to [0, 1]. pow(0, 0) is undefined in GLSL (llvmpipe gives 0), and
// at n = 0 (roughness 1) the lobe is uniform, so 0⁰ is taken as 1.
float cosinePower(float c, float n) {
    float x = clamp(c, 0.0, 1.0);
    return x > 0.0 ? pow(x, n) : (n > 0.0 ? 0.0 : 1.0);
}
