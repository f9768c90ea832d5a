/* ---
id = "shadow.soft"
slot = "shadow"
summary = "Soft shadow by sphere tracing toward the light, penumbra k·h/t"
provides = ["shadow"]
requires = ["map"]
params = { SHADOW_STEPS = { type = "int", default = 24, range = [1, 256] }, SHADOW_K = { type = "float", default = 8.0, range = [1.0, 128.0] } }
sources = ["lighting-model skill, complete code template", "Inigo Quilez, soft shadows"]
--- */
// The nearest miss h at distance t along the ray bounds the visible part of the light;
// larger SHADOW_K gives harder edges.
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float res = 1.0;
    float t = tmin;
    for (int i = 0; i < SHADOW_STEPS; i++) {
        float h = map(ro + rd * t);
        res = min(res, SHADOW_K * h / t);
        t += clamp(h, 0.02, 0.2);
        if (res < 0.001 || t > tmax) break;
    }
    return clamp(res, 0.0, 1.0);
}
