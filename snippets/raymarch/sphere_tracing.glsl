/* ---
id = "raymarch.sphere_tracing"
slot = "raymarch"
summary = "Sphere tracing: distance along the ray to the first hit, or -1"
provides = ["raymarch", "marchTolerance"]
requires = ["map"]
params = { MARCH_STEPS = { type = "int", default = 512, range = [1, 4096] }, MARCH_EPSILON = { type = "float", default = 0.001, range = [1e-6, 0.1] }, MARCH_FAR = { type = "float", default = 50.0, range = [1.0, 10000.0] } }
sources = ["lighting-model skill, complete code template (raymarching)", "Hart 1996"]
formula = 't_0 = 0, \quad t_{i+1} = t_i + d(\mathbf{p}_i), \quad \mathbf{p}_i = \mathbf{o} + t_i \boldsymbol{\omega}, \quad t_{\text{hit}} = t_i \text{ at the first } d(\mathbf{p}_i) < \varepsilon \ (\text{none if } t_i > t_{\text{far}} \text{ or } i = N)'
--- */
// 512 steps: toward a plane seen from height h at a grazing angle, each step closes a fraction
// sin(angle) of the remaining distance, so a hit at distance t takes about (t/h)·ln(h/ε) steps:
// 210 for ground 50 away seen from 1.8. With 128 steps such rays ran out and drew a band of sky
// below the horizon. Only rays that would otherwise end wrongly take the extra steps.
float raymarch(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < MARCH_STEPS; i++) {
        float d = map(ro + rd * t);
        if (d < MARCH_EPSILON) return t;
        t += d;
        if (t > MARCH_FAR) break;
    }
    return -1.0;
}

// How far from the surface a hit may be: the march stops once the distance is under
// MARCH_EPSILON. Shadow rays start that far out along the normal (the scene code's
// hitLift), so that they leave from outside the surface.
float marchTolerance(float t) {
    return MARCH_EPSILON;
}
