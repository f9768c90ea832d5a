/* ---
id = "raymarch.relaxed"
slot = "raymarch"
summary = "Over-relaxed sphere tracing: steps of ω·d while consecutive unbounding spheres overlap, plain steps after the first that does not; stops within a pixel's cone and refines the hit by one secant step"
provides = ["raymarch", "marchTolerance"]
requires = ["map", "sceneSpan"]
params = { MARCH_STEPS = { type = "int", default = 128, range = [1, 1024] }, MARCH_EPSILON = { type = "float", default = 0.001, range = [1e-6, 0.1] }, MARCH_PIXEL = { type = "float", default = 0.002, range = [0.0, 0.05] }, MARCH_FAR = { type = "float", default = 50.0, range = [1.0, 10000.0] }, MARCH_RELAX = { type = "float", default = 1.3, range = [1.0, 1.9] } }
sources = ["Keinert, Schäfer, Korndörfer, Ganse, Stamminger 2014, Enhanced Sphere Tracing (over-relaxation, pixel-cone termination)", "Hart 1996, sphere tracing"]
formula = 't_{i+1} = t_i + \omega\, d_i \text{ while } |d_{i-1}| + |d_i| \ge t_i - t_{i-1}, \text{ else } t_i := t_{i-1} + d_{i-1} \text{ and } \omega := 1, \quad \text{stop at } d_n < \max(\varepsilon, c\, t_n), \quad t_{\text{hit}} = t_n + \frac{d_n\, (t_n - t_{n-1})}{d_{n-1} - d_n} \text{ if } d_n < d_{n-1} \text{ and that lands nearer the surface, else } t_n'
--- */
// raymarch.cone with over-relaxed steps. Where a field is 1-Lipschitz and zero on the surface,
// |d(p)| = |d(p) − d(q)| ≤ |p − q| for every surface point q: no surface lies within |d(p)| of
// p. So a ray may move on by more than d, ω·d, as long as the spheres of radius |d| about two
// consecutive samples overlap (|d_prev| + |d| ≥ the step between them): together they cover
// the segment, and no surface can lie on it. This needs only the bound |d| ≤ distance, not an
// exact distance, so it holds as well for user fields, ellipsoids, blends and cuts whose field
// is a bound, not the distance (a bound only shrinks the spheres: more failed steps, never a
// skipped surface). When the spheres do not overlap the step may have passed a surface (a
// thin wall, or into the object): the sample is not trusted, not even as a hit, and the march
// goes back to the previous sample and takes the plain step d_prev from it, which is safe,
// then sphere-traces on (ω = 1). A failed step costs one map() call; along a grazing ray, or
// a surface met head on, the steps of ω·d save more than that. Mean map() calls per ray on the
// probe scene (a unit sphere on the plane y = −1, 4096 camera rays, tests/compose/test_relaxed_march.py):
// raymarch.sphere_tracing 20.8, raymarch.cone 15.9, this 13.6 at ω = 1.3 (13.8 at 1.2, 14.0 at
// 1.4, 15.6 at 1.6: larger steps fail more often, and each failure ends the relaxation).
// With ω = 1 it is raymarch.cone, step for step.
//
// Stopping and refining as in raymarch.cone: the march stops once the scene is within
// MARCH_PIXEL · t of the ray (or MARCH_EPSILON, near the eye) and one secant step through the
// last two samples, which now lie (t − t_prev) apart rather than d_prev, corrects the hit where
// it lands nearer the surface. A step may end inside the surface only where the spheres just
// touch (a plane met head on with an exact distance), and the secant is exact there.
// MARCH_FAR: the march gives up once the plain step from an accepted sample passes it, so that
// no surface before MARCH_FAR is skipped by a relaxed step that lands beyond it.
//
// Only where a surface can be: the composer's sceneSpan gives the part of the ray inside the
// box of the scene's finite objects or up to its planes (compose/bounds.py). The march starts
// where it begins and gives up where it ends, so a ray that passes the scene by (the sky, most
// of the frame in an open scene) costs no map() call at all.
float raymarch(vec3 ro, vec3 rd) {
    vec2 span = sceneSpan(ro, rd);
    float far = min(MARCH_FAR, span.y);
    if (span.x > far) return -1.0;
    float t = span.x;
    float d = far;
    float tPrev = t;  // the last accepted sample, and its distance
    float dPrev = 0.0;
    float omega = MARCH_RELAX;
    bool hit = false;
    for (int i = 0; i < MARCH_STEPS; i++) {
        d = map(ro + rd * t);
        if (dPrev + abs(d) < t - tPrev) {
            // The spheres do not overlap: back to the previous sample, a plain step from it.
            t = tPrev + dPrev;
            omega = 1.0;
            continue;
        }
        if (d < max(MARCH_EPSILON, MARCH_PIXEL * t)) {
            hit = true;
            break;
        }
        if (t + d > far) break;
        tPrev = t;
        dPrev = d;
        t += omega * d;
    }
    if (!hit) return -1.0;
    // Refined outside the loop: a branch taken by some pixels of a SIMD group costs all of them.
    float ahead = d < dPrev ? d * (t - tPrev) / (dPrev - d) : 0.0;
    float dAhead = map(ro + rd * (t + ahead));
    return abs(dAhead) < abs(d) ? t + ahead : t;
}

// How far from the surface a hit may be at distance t, as in raymarch.cone; shadow rays
// start that far out along the normal.
float marchTolerance(float t) {
    return max(MARCH_EPSILON, MARCH_PIXEL * t);
}
