/* ---
id = "sss.sdf_probe"
slot = "sss"
summary = "Transmittance toward L through the SDF: exp(−σ·t), t the inside length of 5 midpoint taps"
provides = ["subsurface"]
requires = ["map"]
reference = "subsurface_sphere"
error_budget = { max_abs = 0.26 }
budget_why = "Five midpoint taps resolve the chord to half a cell: the error is at most 1 − exp(−σ·SSS_STEP/2) = 0.26 at the defaults, mostly where the ray skims the surface (measured 0.259); the budget is that bound."
sources = [
    "lighting-model skill, common variants (SSS: SDF interior probing)",
    "Pharr, Jakob and Humphreys, PBRT 3rd ed., 11.1 (Beer's law)",
]
formula = 'T = \exp\left( -\sigma\, \Delta \sum_{i=0}^{4} \left[ d\left( \mathbf{p} + (i + \tfrac{1}{2}) \Delta\, \mathbf{l} \right) < 0 \right] \right), \quad \sigma = \text{SSS\_EXTINCTION}, \quad \Delta = \text{SSS\_STEP}'
params = { SSS_EXTINCTION = { type = "float", default = 6.0, range = [0.0, 100.0] }, SSS_STEP = { type = "float", default = 0.1, range = [0.01, 1.0] } }
--- */
// Light reaching the surface point p from the inside, through the body, toward the light L:
// the exact value is exp(−σ·c), c the length of the ray p + tL (t > 0) inside the body (its
// chord). Five taps at the midpoints of cells of SSS_STEP along L count a cell as inside when
// the distance field is negative there, so t̂ is the midpoint rule for the inside length
// within 5·SSS_STEP. Errors (tests/test_subsurface.py, spheres of radius 0.05 to 100): a
// cell is half-resolved, so |exp(−σt̂) − exp(−σc)| ≤ 1 − exp(−σ·SSS_STEP/2) = 0.26 at the
// defaults, mostly where the ray skims the surface; bodies thicker than 5·SSS_STEP = 0.5 read
// as 0.5 (transmittance below exp(−3) = 0.05 either way). A binary count is used on purpose:
// a ramp in the distance (the seed's max(0, h − d)) counts rays that graze the outside of a
// flat surface as half inside.
float subsurface(vec3 p, vec3 L) {
    float inside = 0.0;
    for (int i = 0; i < 5; i++) {
        float t = SSS_STEP * (float(i) + 0.5);
        inside += 1.0 - step(0.0, map(p + L * t));
    }
    return exp(-SSS_EXTINCTION * SSS_STEP * inside);
}
