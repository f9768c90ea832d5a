/* ---
id = "ao.sdf3"
slot = "ao"
summary = "SDF ambient occlusion, 3 taps along the normal (cheaper, for far or small surfaces)"
provides = ["ambientOcclusion"]
requires = ["map"]
params = { AO_STRENGTH = { type = "float", default = 3.0, range = [0.0, 10.0] } }
sources = ["lighting-model skill, step 9 (\"can reduce to 3 at far distances\")", "Inigo Quilez, SDF ambient occlusion"]
formula = '\text{AO} = \operatorname{clamp}\left( 1 - k \sum_{i=0}^{2} \tfrac{5}{3}\, 0.9025^{i} \left( h_i - d(\mathbf{p} + h_i \mathbf{n}) \right),\ 0,\ 1 \right), \quad h_i = 0.01 + 0.06\, i, \quad k = \text{AO\_STRENGTH}'
reference = "ao_cosine_visibility"
# Measured like ao.sdf5: max 0.244, mean 0.0064, 0.079 where occluded.
error_budget = { max_abs = 0.3, mean_abs = 0.008 }
budget_why = "A heuristic, not an estimator: against cosine-weighted visibility it is off by up to 0.244, 0.0064 on average over 5564 points (0.079 where occluded); the budget is about 1.25x those."
--- */
// ao.sdf5 with every other tap: the same heights 0.01 to 0.13 along n, the same decay per unit
// of height (0.95 per 0.03, so 0.95² per tap here), and each tap weighed 5/3 so that AO_STRENGTH
// means what it means in ao.sdf5 (the weights sum to about the same).
float ambientOcclusion(vec3 p, vec3 n) {
    float occ = 0.0;
    float weight = 5.0 / 3.0;
    for (int i = 0; i < 3; i++) {
        float h = 0.01 + 0.06 * float(i);
        occ += (h - map(p + h * n)) * weight;
        weight *= 0.9025;
    }
    return clamp(1.0 - AO_STRENGTH * occ, 0.0, 1.0);
}
