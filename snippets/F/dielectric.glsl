/* ---
id = "F.dielectric"
slot = "F"
summary = "Exact unpolarised Fresnel of the dielectric whose IOR gives f0"
provides = ["fresnel", "MAX_SQRT_F0", "MIN_FRESNEL_DENOM"]
requires = []
domain = { f0 = [0, 0.99], cosTheta = [0, 1] }
reference = "F_dielectric"
error_budget = { max_abs = 1e-5, max_rel = 1e-4 }
budget_why = "The exact formula, written without the textbook cancellations: float32 rounding only, measured 5.1e-7 absolute and 6.3e-7 relative (worst at f0 = 0.99, grazing) on llvmpipe; the budget leaves about 20x and 150x."
sources = ["Walter et al. 2007, eq. 22", "Born & Wolf, Principles of Optics, 1.5.2"]
formula = 'F = \frac{1}{2} \left( \frac{g - c}{g + c} \right)^2 \left( 1 + \left( \frac{c (g + c) - 1}{c (g - c) + 1} \right)^2 \right), \quad g = \sqrt{\eta^2 - 1 + c^2}, \quad \eta = \frac{1 + \sqrt{F_0}}{1 - \sqrt{F_0}}, \quad c = \cos\theta'
--- */
// Largest √f0: η = (1 + √f0)/(1 − √f0) is infinite at f0 = 1; 0.9999 keeps η² ≈ 4·10⁸.
#define MAX_SQRT_F0 0.9999
// Floor of (g + c)²: it is 0 at f0 = 0 (η = 1) and grazing incidence.
#define MIN_FRESNEL_DENOM 1e-30

// Per channel, η = (1 + √f0)/(1 − √f0), g = √(η² − 1 + c²) and
// F = ½ ((g − c)/(g + c))² (1 + ((c(g + c) − 1)/(c(g − c) + 1))²).
// η² − 1 is taken as 4√f0/(1 − √f0)² and g − c as (η² − 1)/(g + c), without the
// cancellations of the textbook form at small f0. With η ≥ 1 there is no total internal
// reflection. For a conductor's f0 this is a stand-in with the right ends (f0 at 0°, 1 at 90°).
vec3 fresnel(vec3 f0, float cosTheta) {
    float c = clamp(cosTheta, 0.0, 1.0);
    vec3 s = min(sqrt(clamp(f0, 0.0, 1.0)), vec3(MAX_SQRT_F0));
    vec3 k = 4.0 * s / ((1.0 - s) * (1.0 - s));
    vec3 g = sqrt(k + c * c);
    vec3 gPlusC = g + c;
    vec3 gMinusC = k / max(gPlusC, vec3(MIN_FRESNEL_DENOM));
    vec3 A = gMinusC / max(gPlusC, vec3(MIN_FRESNEL_DENOM));
    vec3 B = (c * gPlusC - 1.0) / (c * gMinusC + 1.0);
    return 0.5 * A * A * (1.0 + B * B);
}
