/* ---
id = "media.beer"
slot = "media"
summary = "Beer-Lambert extinction with constant in-scatter: color·T + inscatter·(1 − T), T = exp(−σ·dist)"
provides = ["medium", "MEDIUM_LOG2_E"]
requires = []
domain = { color0 = [0, 1], color1 = [0, 1], color2 = [0, 1], dist = [0, 20] }
reference = "medium_beer"
error_budget = { max_abs = 3e-7, max_rel = 5e-7 }
budget_why = "Float32 rounding of exp2(−σd·log2 e) and the blend: measured 1.1e-7 absolute and 1.6e-7 relative on llvmpipe; the budget leaves about 3x."
sources = [
    "lighting-model skill, common variants (Beer's law water lighting)",
    "Pharr, Jakob and Humphreys, PBRT 3rd ed., 11.1 (Beer's law)",
]
formula = 'C = T\, C_{\text{surface}} + (1 - T)\, C_{\text{inscatter}}, \quad T = e^{-\sigma \max(d, 0)}'
# σ per unit distance, per channel (natural log): the skill's water, exp2(−6·(0.5, 0.6, 0.9)·d),
# is σ = 6 ln 2 · (0.5, 0.6, 0.9). Red goes first, blue last.
[params.MEDIUM_EXTINCTION]
type = "vec3"
default = [2.0794415, 2.4953298, 3.7429947]
# What a long path through the medium converges to: the light the water itself scatters toward
# the eye (its colour under the ambient light).
[params.MEDIUM_INSCATTER]
type = "vec3"
default = [0.02, 0.12, 0.16]
--- */
// log2(e): exp(−x) is computed as exp2(−x·log2 e), the form GPUs evaluate natively.
#define MEDIUM_LOG2_E 1.4426950408889634

// Radiance `color` leaving a surface at distance `dist` behind a homogeneous medium that
// absorbs and scatters with coefficient σ and glows with MEDIUM_INSCATTER: the transmittance
// T = exp(−σ d) (Beer-Lambert) weighs the surface, 1 − T the medium, so that a long path
// tends to the medium's colour. Single in-scatter of a uniformly lit medium: the in-scatter
// and extinction share one σ (the skill's water used a separate, slower rate for it).
vec3 medium(vec3 color, float dist) {
    vec3 transmittance = exp2(-max(dist, 0.0) * MEDIUM_LOG2_E * MEDIUM_EXTINCTION);
    return mix(MEDIUM_INSCATTER, color, transmittance);
}
