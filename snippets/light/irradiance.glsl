/* ---
id = "light.irradiance"
slot = "light"
summary = "Diffuse light from the whole environment, by the irradiance slot, occluded by AO"
provides = ["irradianceLight"]
requires = ["Surface", "irradiance"]
sources = ["lighting-model skill, variant 3 (diffuse IBL: diffuseColor · SHIrradiance(N))"]
formula = 'L_o = \rho\, \frac{E(\mathbf{n})}{\pi}\, s\, \text{occ}'
--- */
// irradiance(n) is E/π, so a Lambert surface reflects diffuseColor times it.
vec3 irradianceLight(Surface s, float scale, float occlusion) {
    return s.diffuseColor * irradiance(s.N) * (scale * occlusion);
}
