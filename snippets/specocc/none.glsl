/* ---
id = "specocc.none"
slot = "specocc"
summary = "No specular occlusion: the environment reflection is seen unoccluded"
provides = ["specularOcclusion"]
requires = []
domain = { NoV = [0.0001, 1], ao = [0, 1], a = [0, 1] }
reference = "specular_visible_fraction"
error_budget = { max_abs = 1.0, rms = 0.7 }
budget_why = "It sees every reflection unoccluded, so its error is the occluded share of the lobe itself: all of it where ao = 0 (max 1), RMS 0.66 over the domain, measured against the lobe seen through the AO's cone; the budget is that design error."
sources = ["Lagarde and de Rousiers 2014 (what specular occlusion corrects)"]
formula = '\text{SO} = 1'
--- */
// The planner picks it when the scene has no AO to derive an occlusion from: with ao = 1 every
// AO-based variant returns 1 anyway, so this is the same picture for no code.
float specularOcclusion(float NoV, float ao, float a) {
    return 1.0;
}
