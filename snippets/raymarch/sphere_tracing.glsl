/* ---
id = "raymarch.sphere_tracing"
slot = "raymarch"
summary = "Sphere tracing: distance along the ray to the first hit, or -1"
provides = ["raymarch"]
requires = ["map"]
params = { MARCH_STEPS = { type = "int", default = 128, range = [1, 1024] }, MARCH_EPSILON = { type = "float", default = 0.001, range = [1e-6, 0.1] }, MARCH_FAR = { type = "float", default = 50.0, range = [1.0, 10000.0] } }
sources = ["lighting-model skill, complete code template (raymarching)", "Hart 1996"]
formula = 't_0 = 0, \quad t_{i+1} = t_i + d(\mathbf{p}_i), \quad \mathbf{p}_i = \mathbf{o} + t_i \boldsymbol{\omega}, \quad t_{\text{hit}} = t_i \text{ at the first } d(\mathbf{p}_i) < \varepsilon \ (\text{none if } t_i > t_{\text{far}} \text{ or } i = N)'
--- */
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
