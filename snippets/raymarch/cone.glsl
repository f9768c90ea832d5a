/* ---
id = "raymarch.cone"
slot = "raymarch"
summary = "Sphere tracing that stops once the scene is within a pixel's cone, then refines the hit by one secant step"
provides = ["raymarch", "marchTolerance"]
requires = ["map"]
params = { MARCH_STEPS = { type = "int", default = 128, range = [1, 1024] }, MARCH_EPSILON = { type = "float", default = 0.001, range = [1e-6, 0.1] }, MARCH_PIXEL = { type = "float", default = 0.002, range = [0.0, 0.05] }, MARCH_FAR = { type = "float", default = 50.0, range = [1.0, 10000.0] } }
sources = ["Hart 1996, sphere tracing", "Keinert et al. 2014, Enhanced Sphere Tracing (pixel-cone termination)"]
formula = 't_{i+1} = t_i + d_i, \quad d_i = d(\mathbf{o} + t_i \boldsymbol{\omega}), \quad \text{stop at } d_n < \max(\varepsilon, c\, t_n), \quad t_{\text{hit}} = t_n + \frac{d_n\, d_{n-1}}{d_{n-1} - d_n} \text{ if } d_n < d_{n-1} \text{ and that lands nearer the surface, else } t_n'
--- */
// A pixel sees a cone about 2 / (iResolution.y · focal) radians wide. Once the scene is nearer
// the ray than MARCH_PIXEL · t (or MARCH_EPSILON, near the eye) the march stops: more steps
// would not change which surface the pixel shows. A grazing ray along a plane shrinks its
// distance only by a factor 1 − sin θ per step, so the fixed tolerance of
// raymarch.sphere_tracing spends most of its steps there (or all of them, and misses).
// MARCH_PIXEL = 0.002 is about half a pixel at 640 × 360 with a focal length of 1.5. At 64
// steps, 71 of the 4096 probe camera rays (samples.camera_rays) used every step, far ground near
// the horizon that then showed sky; at 128 they reach it, and the rays that converge sooner
// cost the same.
//
// Stopping early leaves the hit short of the surface, along a grazing ray by d / sin θ, about
// a pixel's footprint: texture edges would move. Along a straight stretch the distance falls
// linearly with t, so the last two samples (d_prev one plain step of d_prev behind, d here)
// say where it reaches 0: d · d_prev / (d_prev − d) further on, exact for a plane. One more
// map() checks the secant point and it is kept only where it lies nearer the surface.
float raymarch(vec3 ro, vec3 rd) {
    float t = 0.0;
    float d = MARCH_FAR;
    float dPrev = 0.0;  // distance at the previous sample, which lies dPrev behind t
    bool hit = false;
    for (int i = 0; i < MARCH_STEPS; i++) {
        d = map(ro + rd * t);
        if (d < max(MARCH_EPSILON, MARCH_PIXEL * t)) {
            hit = true;
            break;
        }
        dPrev = d;
        t += d;
        if (t > MARCH_FAR) break;
    }
    if (!hit) return -1.0;
    // Refined outside the loop: a branch taken by some pixels of a SIMD group costs all of them.
    float ahead = d < dPrev ? d * dPrev / (dPrev - d) : 0.0;
    float dAhead = map(ro + rd * (t + ahead));
    return abs(dAhead) < abs(d) ? t + ahead : t;
}

// How far from the surface a hit may be at distance t: the pixel cone's radius there (or
// MARCH_EPSILON near the eye). Shadow rays start that far out along the normal (the scene
// code's hitLift): a hit accepted that far off a concave rim would otherwise shadow itself
// (a dark hairline).
float marchTolerance(float t) {
    return max(MARCH_EPSILON, MARCH_PIXEL * t);
}
