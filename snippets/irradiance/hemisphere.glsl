/* ---
id = "irradiance.hemisphere"
slot = "irradiance"
summary = "Irradiance/π as a blend of the environment straight up and straight down by 0.5 + 0.5·n.y"
provides = ["irradiance"]
requires = ["env"]
domain = { n0 = [-1, 1], n1 = [-1, 1], n2 = [-1, 1] }
reference = "irradiance_gradient"
error_budget = { max_abs = 0.051 }
budget_why = "Blending up and down by 0.5 + 0.5·n.y is exact only for a two-colour world: under env.gradient it is off by |top − bottom|·|n.y|/6, measured 0.0499 facing straight down; the budget is that design error."
sources = [
    "lighting-model skill, performance notes (simplified IBL: mix(ground, sky, y*0.5+0.5))",
    "Ramamoorthi and Hanrahan 2001 (irradiance of a linear gradient)",
]
formula = '\frac{E(\mathbf{n})}{\pi} = L_{\text{env}}(-\hat{\mathbf{y}}) + \left( L_{\text{env}}(\hat{\mathbf{y}}) - L_{\text{env}}(-\hat{\mathbf{y}}) \right) \frac{1 + n_y}{2}'
--- */
// Exact for a two-colour world (sky above the horizon, ground below): the share of the cosine
// lobe above the horizon is (1 + n.y)/2. For a sky that varies smoothly with height it blends
// too steeply: under env.gradient the exact value is bottom + (top − bottom)(1/2 + n.y/3), so
// the error is |top − bottom|·|n.y|/6, largest facing straight up or down.
vec3 irradiance(vec3 n) {
    vec3 sky = environment(vec3(0.0, 1.0, 0.0));
    vec3 ground = environment(vec3(0.0, -1.0, 0.0));
    return mix(ground, sky, 0.5 + 0.5 * n.y);
}
