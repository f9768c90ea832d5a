/* ---
id = "normal.derivative_flat"
slot = "normal"
summary = "Flat (faceted) normal from the screen-space derivatives of the hit position; SDF taps only where a pixel quad straddles two surfaces"
provides = ["calcNormal"]
requires = ["map"]
params = { NORMAL_EPS = { type = "float", default = 0.001, range = [1e-6, 0.1] } }
reference = "sdf_normal"
error_budget = { max_deg = 0.02, mean_deg = 0.002 }
budget_why = "A loose bound: on flat faces with an exact hit position the derivatives' cross product is exact but for float32, measured max 0.0014° and mean 0.00012° over 15550 pixels on llvmpipe; the budget is about 15x."
sources = ["OpenGL ES Shading Language 3.00, section 8.9 (derivative functions)", "Inigo Quilez, normals for an SDF (derivative-based normals)"]
formula = '\mathbf{n} = \frac{\partial_x \mathbf{p} \times \partial_y \mathbf{p}}{\|\partial_x \mathbf{p} \times \partial_y \mathbf{p}\|} \text{ unless } |d(\mathbf{p} + \tfrac{1}{2} \partial_{x,y} \mathbf{p})| > \tfrac{1}{4} \|\partial_{x,y} \mathbf{p}\| \text{, then the tetrahedron estimate of } \nabla d'
--- */
// dFdx(p) and dFdy(p) are two vectors across the surface, one pixel apart on screen, so their
// cross product is perpendicular to the surface as the pixel grid sees it: exact on flat faces,
// faceted on curved ones (constant over each 2x2 pixel quad where the driver takes coarse
// derivatives). On flat faces it is as good as the hit position is smooth from pixel to pixel:
// with an exact intersection 0.001°, behind sphere tracing the hit's jitter (up to
// MARCH_EPSILON) tilts it (measured on a box: 1.4° at MARCH_EPSILON = 1e-3, 0.15° at 1e-4).
//
// Where a quad straddles two surfaces (a silhouette against the ground behind it, or the sky's
// far point) the difference spans the gap between them, and the cross product is no normal of
// either: shaded, those quads drew a dark dotted ring around objects. Such a quad is found with
// two taps: the midpoint between p and its neighbour lies on the surface when both pixels see
// one smooth surface (off it by |Δp|²/8R on a curve of radius R), and in the open, a good
// fraction of a pixel's footprint away, when they see two. The footprint is the shorter of the
// two steps, since a grazing view stretches only the other (a plane seen at grazing keeps its
// midpoints on it however long the step). There the normal falls back to the four taps of
// normal.tetrahedron, correct whatever the neighbours hit; so does a surface curved on the
// scale of a pixel, where a flat facet would be no normal either.
//
// The sign is left to the caller: the cross product points toward the viewer for a camera whose
// right × up points back at the eye and the runner's dFdy follows fragCoord's y, but a runner
// that flips fragCoord and not dFdy (wgpu-shadertoy) turns it inward. The composer orients it
// toward the eye with faceforward(n, rd, n), which needs the ray; testing the SDF would need taps.
//
// Derivatives are undefined in non-uniform control flow (GLSL ES 3.00 §8.9): call this where
// every pixel of the 2x2 quad runs it, e.g. before `if (hit)`, never inside it.
vec3 calcNormal(vec3 p) {
    vec3 dx = dFdx(p);
    vec3 dy = dFdy(p);
    vec3 n = cross(dx, dy);
    // How far the midpoints toward the two neighbours lie off any surface, against a quarter of
    // the shorter step: a grazing view stretches one step, never the other.
    float gap = max(abs(map(p + 0.5 * dx)), abs(map(p + 0.5 * dy)));
    float across = 0.25 * min(length(dx), length(dy));
    // Also where the pixel grid does not span a surface (p the same across the quad).
    if (gap > across || dot(n, n) < 1e-30) {
        const vec2 k = vec2(1.0, -1.0);
        float h = NORMAL_EPS * 0.5773502691896258;  // NORMAL_EPS / √3, as normal.tetrahedron
        n = k.xyy * map(p + k.xyy * h) + k.yyx * map(p + k.yyx * h) +
            k.yxy * map(p + k.yxy * h) + k.xxx * map(p + k.xxx * h);
    }
    return normalize(n);
}
