/* ---
id = "light.directional"
slot = "light"
summary = "Directional light: diffuse and specular lobes times radiance and visibility"
provides = ["directionalLight"]
requires = ["Surface", "Dots", "lightDots", "F", "diffuse", "specular"]
sources = ["lighting-model skill, step 8 and complete code template"]
--- */
// The diffuse share is what the Fresnel term does not reflect (energy split). Each lobe
// carries its own cosine factor, so a wrapped diffuse model can light past the terminator.
vec3 directionalLight(Surface s, vec3 L, vec3 radiance, float visibility) {
    Dots d = lightDots(s, L);
    vec3 F = fresnel(s.f0, d.VoH);
    vec3 reflected = (1.0 - F) * diffuse(s, d) + specular(s, d, F);
    return reflected * radiance * visibility;
}
