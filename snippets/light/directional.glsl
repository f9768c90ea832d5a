/* ---
id = "light.directional"
slot = "light"
summary = "Directional light: the surface's response times radiance and visibility"
provides = ["directionalLight"]
requires = ["Surface", "lightResponse"]
sources = ["lighting-model skill, step 8 and complete code template"]
formula = 'L_o = R(\mathbf{l})\, L_{\text{light}}\, S'
--- */
// `visibility` is per channel, so a shadow can tint its penumbra (see the scene's `penumbra`).
vec3 directionalLight(Surface s, vec3 L, vec3 radiance, vec3 visibility) {
    return lightResponse(s, L) * radiance * visibility;
}
