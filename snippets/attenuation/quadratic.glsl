/* ---
id = "attenuation.quadratic"
slot = "attenuation"
summary = "Constant-linear-quadratic falloff 1 / (1 + 0.1 d + 0.01 d²); ignores the range"
provides = ["attenuation"]
requires = []
params = { ATTEN_LINEAR = { type = "float", default = 0.1, range = [0.0, 10.0] }, ATTEN_QUADRATIC = { type = "float", default = 0.01, range = [0.0, 10.0] } }
domain = { dist = [0, 1000], range = [0, 100] }
reference = "attenuation_quadratic"
error_budget = { max_abs = 1e-7, max_rel = 1e-6 }
budget_why = "Float32 rounding only: measured 1.0e-8 absolute and 1.2e-7 relative on llvmpipe for values in (0, 1]; the budget leaves about 10x and 8x."
sources = ["lighting-model skill, point light attenuation", "OpenGL 1.x fixed-function lighting (GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION)"]
formula = 'A(d) = \frac{1}{1 + k_l\, d + k_q\, d^2}, \quad k_l = \text{ATTEN\_LINEAR} = 0.1, \quad k_q = \text{ATTEN\_QUADRATIC} = 0.01'
--- */
// The classic artist's falloff: 1 at the light, never infinite, and 100/d² far away (so a light
// of this family is 100 times brighter at a distance than the same intensity under 1/d²). It is
// not physical and never reaches zero, so `range` is not used: the light touches everything, and
// a scene must bound its cost some other way. Kept for the seed template's look; prefer
// attenuation.inverse_square_range for physically based intensities.
// With non-negative coefficients the denominator is at least 1 for d ≥ 0: always finite, and a
// huge d (d² → +∞) gives exactly 0.
float attenuation(float dist, float range) {
    return 1.0 / (1.0 + ATTEN_LINEAR * dist + ATTEN_QUADRATIC * dist * dist);
}
