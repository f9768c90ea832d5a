/* ---
id = "shadow.hard"
slot = "shadow"
summary = "Hard shadow: 0 if the ray toward the light hits the scene, else 1"
provides = ["shadow"]
requires = ["map"]
params = { SHADOW_STEPS = { type = "int", default = 64, range = [1, 256] } }
sources = ["Inigo Quilez, soft shadows (the hard case)"]
reference = "shadow_ray"
error_budget = { mean_abs = 0.003 }  # 0/1 output: the share of points whose verdict differs
--- */
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float t = tmin;
    for (int i = 0; i < SHADOW_STEPS; i++) {
        float h = map(ro + rd * t);
        if (h < 0.001) return 0.0;
        t += h;
        if (t > tmax) break;
    }
    return 1.0;
}
