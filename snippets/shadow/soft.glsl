/* ---
id = "shadow.soft"
slot = "shadow"
summary = "Soft shadow by sphere tracing toward the light, penumbra k·h/t (24 steps)"
provides = ["shadow"]
requires = ["map"]
params = { SHADOW_STEPS = { type = "int", default = 24, range = [1, 256] }, SHADOW_K = { type = "float", default = 8.0, range = [1.0, 128.0] } }
sources = ["lighting-model skill, complete code template", "Inigo Quilez, soft shadows in raymarched SDFs (2010)"]
formula = 'S = \operatorname{clamp}\left( \min_i \frac{k\, h_i}{t_i},\ 0,\ 1 \right), \quad h_i = d(\mathbf{o} + t_i \boldsymbol{\omega}), \quad t_0 = \max(t_{\min}, 10^{-3}), \quad t_{i+1} = t_i + \operatorname{clamp}(h_i, 0.02, 0.2), \quad t_i \le t_{\max},\ i < N'
reference = "shadow_disc_light"
# Against a disc light of angular radius atan(1/k): max 0.91 (a low sun's far occluder is out
# of reach of 24 steps), mean 0.018 over 10460 points, 0.24 in the penumbrae.
error_budget = { max_abs = 1.0, mean_abs = 0.023 }
budget_why = "k·h/t against a disc light of angular radius atan(1/k): mean 0.018 over 10460 points, 0.24 in penumbrae, max 0.91 where a low sun's far occluder is beyond 24 steps; the budget is about 1.3x the mean, max 1."
--- */
// A miss by h at distance t along the ray leaves a gap of about h/t radians between the ray
// and the occluder; the light counts as fully visible once every gap is at least 1/SHADOW_K,
// i.e. for a light of angular radius about atan(1/SHADOW_K). The penumbra lies outside the
// hard shadow: a ray that grazes an occluder gives 0. Larger SHADOW_K gives harder edges.
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float res = 1.0;
    float t = max(tmin, 1e-3);  // h/t has no value at t = 0
    for (int i = 0; i < SHADOW_STEPS; i++) {
        float h = map(ro + rd * t);
        res = min(res, SHADOW_K * h / t);
        // At least 0.02 so the march moves on beside a surface, at most 0.2 so the closest
        // approach to an occluder is not stepped over.
        t += clamp(h, 0.02, 0.2);
        if (res < 0.001 || t > tmax) break;
    }
    return clamp(res, 0.0, 1.0);
}
