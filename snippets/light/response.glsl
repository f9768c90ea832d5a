/* ---
id = "light.response"
slot = "light"
summary = "What a surface reflects toward the eye per unit radiance arriving from L: diffuse and specular lobes"
provides = ["lightResponse"]
requires = ["Surface", "Dots", "lightDots", "F", "diffuse", "specular"]
sources = ["lighting-model skill, step 8 and complete code template"]
formula = 'R(\mathbf{l}) = \left( 1 - F(\mathbf{v} \cdot \mathbf{h}) \right) f_d\, (\mathbf{n} \cdot \mathbf{l}) + f_s\, (\mathbf{n} \cdot \mathbf{l})'
--- */
// The diffuse share is what the Fresnel term does not reflect (energy split). Each lobe
// carries its own cosine factor, so a wrapped diffuse model can light past the terminator.
vec3 lightResponse(Surface s, vec3 L) {
    Dots d = lightDots(s, L);
    vec3 F = fresnel(s.f0, d.VoH);
    return (1.0 - F) * diffuse(s, d) + specular(s, d, F);
}
