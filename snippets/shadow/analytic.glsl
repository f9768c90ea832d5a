/* ---
id = "shadow.analytic"
slot = "shadow"
summary = "Soft shadow from the exact angular clearance of the ray from each analytic primitive: no march"
provides = ["shadow"]
requires = ["sceneClearance"]
params = { SHADOW_K = { type = "float", default = 8.0, range = [1.0, 128.0] } }
sources = ["Inigo Quilez, sphere soft shadow (closed form)", "Inigo Quilez, improved soft shadows with inner penumbra (2020)"]
formula = 'S = \tfrac{1}{4} (1 + x)^2 (2 - x), \quad x = \operatorname{clamp}\left( \frac{\min_k \delta_k}{\arctan(1/k)}, -1, 1 \right), \quad \delta_k = \text{signed angle from the ray to the outline of object } k'
reference = "shadow_disc_light"
# Against a disc light of angular radius atan(1/k), over the shadow cases of the reference
# scenes: mean 0.0029, max 0.23 (shadow.soft_centered: 0.0044, 0.27). What is left is the cubic
# fit of a straight edge, and the least clearance taken where two occluders both cut the disc.
error_budget = { max_abs = 0.25, mean_abs = 0.0035 }
budget_why = "The cubic fit of a straight edge and the least clearance where two occluders cut the disc: against a disc light, max 0.23 and mean 0.0029 over 10460 points; the budget is about 1.1x and 1.2x that."
--- */
// shadow.soft_centered estimates x, the ray's signed angular distance to an occluder's edge in
// units of the light's radius atan(1/k), from samples k·h/t of a march. For a sphere, a box or
// a plane that angle has a closed form (snippets/trace/: the outline of a sphere is a circle, a
// box's is made of its silhouette edges, a half-space's horizon is a great circle), so here it
// is exact and costs one evaluation per object instead of up to SHADOW_STEPS of the scene. The
// disc's visible fraction is then the same cubic fit of a straight edge as soft_centered's.
// The ray starts tmin along rd, as the march does: a point on a surface is then off it on the
// side the light is, and occluded by it only when the light is below its tangent plane.
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float radius = max(atan(1.0 / SHADOW_K), 1e-6);  // the disc light's angular radius
    float x = sceneClearance(ro + rd * tmin, rd, tmax, radius) / radius;
    x = clamp(x, -1.0, 1.0);
    return 0.25 * (1.0 + x) * (1.0 + x) * (2.0 - x);
}
