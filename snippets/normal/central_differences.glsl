/* ---
id = "normal.central_differences"
slot = "normal"
summary = "SDF normal by central differences, 6 taps"
provides = ["calcNormal"]
requires = ["map"]
params = { NORMAL_EPS = { type = "float", default = 0.001, range = [1e-6, 0.1] } }
reference = "sdf_normal"
error_budget = { max_deg = 0.2, mean_deg = 0.005 }
budget_why = "Truncation of second order in NORMAL_EPS = 0.001 plus float32 taps: measured max 0.066° (smooth union) and mean under 0.0016° on each reference scene on llvmpipe; the budget is about 3x that."
sources = ["lighting-model skill, step 1"]
formula = '\mathbf{n} = \operatorname{normalize}\left( d(\mathbf{p} + \varepsilon \mathbf{e}_i) - d(\mathbf{p} - \varepsilon \mathbf{e}_i) \right)_{i = x, y, z}, \quad \varepsilon = \text{NORMAL\_EPS}'
--- */
vec3 calcNormal(vec3 p) {
    vec2 e = vec2(NORMAL_EPS, 0.0);
    return normalize(vec3(
        map(p + e.xyy) - map(p - e.xyy),
        map(p + e.yxy) - map(p - e.yxy),
        map(p + e.yyx) - map(p - e.yyx)
    ));
}
