/* ---
id = "normal.derivative_flat"
slot = "normal"
summary = "Flat (faceted) normal from the screen-space derivatives of the hit position, no SDF taps"
provides = ["calcNormal"]
requires = []
params = { DERIVATIVE_NORMAL_SIGN = { type = "float", default = 1.0, range = [-1.0, 1.0] } }
reference = "sdf_normal"
error_budget = { max_deg = 0.02, mean_deg = 0.002 }
sources = ["OpenGL ES Shading Language 3.00, section 8.9 (derivative functions)", "Inigo Quilez, normals for an SDF (derivative-based normals)"]
formula = '\mathbf{n} = s\, \frac{\partial_x \mathbf{p} \times \partial_y \mathbf{p}}{\|\partial_x \mathbf{p} \times \partial_y \mathbf{p}\|}, \quad s = \text{DERIVATIVE\_NORMAL\_SIGN}'
--- */
// dFdx(p) and dFdy(p) are two vectors across the surface, one pixel apart on screen, so their
// cross product is perpendicular to the surface as the pixel grid sees it: exact on flat faces,
// faceted on curved ones (constant over each 2x2 pixel quad where the driver takes coarse
// derivatives), and wrong where a quad straddles two faces or a silhouette. It costs no map().
// On flat faces it is as good as the hit position is smooth from pixel to pixel: with an exact
// intersection 0.001°, behind sphere tracing the hit's jitter (up to MARCH_EPSILON) tilts it
// (measured on a box: 1.4° at MARCH_EPSILON = 1e-3, 0.15° at 1e-4).
//
// The sign. A camera whose right × up points back toward the eye (both catalog cameras: uu =
// ww × worldUp, vv = uu × ww, so uu × vv = −ww) maps every surface it can see onto the screen
// with its orientation kept, so dFdx(p) × dFdy(p) points toward the viewer, which for the first
// hit of a ray is out of the surface. A mirrored camera (left-handed basis, or a flipped y) turns
// it inward: set DERIVATIVE_NORMAL_SIGN to -1.0 for it. Testing the SDF instead would cost the
// taps this variant exists to avoid.
//
// Caveat: derivatives are undefined in non-uniform control flow (GLSL ES 3.00 §8.9). Call this
// where every pixel of the 2x2 quad runs it, e.g. before `if (hit)`, never inside it; inside, the
// neighbours that missed hold no meaningful p and silhouette pixels get arbitrary normals.
vec3 calcNormal(vec3 p) {
    vec3 n = cross(dFdx(p), dFdy(p));
    // Zero where the pixel grid does not span the surface (p constant across the quad).
    return DERIVATIVE_NORMAL_SIGN * n * inversesqrt(max(dot(n, n), 1e-30));
}
