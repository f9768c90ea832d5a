/* ---
id = "core.metallic"
slot = "core"
summary = "Metallic workflow: a metal reflects its albedo and has no diffuse"
provides = ["applyMetallic"]
requires = ["Surface"]
sources = ["lighting-model skill, step 8", "Filament PBR notes, 4.8 (metallic parameterization)"]
formula = '\rho_d = (1 - m)\, \rho, \quad F_0 = (1 - m)\, F_{0,\text{dielectric}} + m\, \rho, \quad m = \text{metallic}'
--- */
// Turns the dielectric that makeSurface built into a blend toward a metal of the same albedo:
// metals tint their reflection with the albedo and absorb what they refract, so their diffuse
// is zero. Emitted only for scenes with a metallic material. Called right after makeSurface,
// so s.f0 still holds the dielectric's reflectance.
void applyMetallic(inout Surface s, vec3 albedo, float metallic) {
    s.diffuseColor = albedo * (1.0 - metallic);
    s.f0 = mix(s.f0, albedo, metallic);
}
