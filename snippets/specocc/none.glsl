/* ---
id = "specocc.none"
slot = "specocc"
summary = "No specular occlusion: the environment reflection is seen unoccluded"
provides = ["specularOcclusion"]
requires = []
domain = { NoV = [0, 1], ao = [0, 1], a = [0, 1] }
sources = ["Lagarde and de Rousiers 2014 (what specular occlusion corrects)"]
formula = '\text{SO} = 1'
--- */
// The planner picks it when the scene has no AO to derive an occlusion from: with ao = 1 every
// AO-based variant returns 1 anyway, so this is the same picture for no code.
float specularOcclusion(float NoV, float ao, float a) {
    return 1.0;
}
