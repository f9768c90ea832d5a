/* ---
id = "light.point"
slot = "light"
summary = "Point light: the surface's response times radiance, distance attenuation and visibility"
provides = ["pointLight"]
requires = ["Surface", "lightResponse", "attenuation"]
sources = ["lighting-model skill, variant 2 (point light attenuation)", "Filament PBR notes, 5.2.2 (punctual lights)"]
formula = 'L_o = R(\mathbf{l})\, L_{\text{light}}\, A(d, r)\, S, \quad \mathbf{l} = \frac{\mathbf{x}_{\text{light}} - \mathbf{p}}{d}, \quad d = \|\mathbf{x}_{\text{light}} - \mathbf{p}\|'
--- */
// The falloff with distance is the `attenuation` slot's choice (inverse square with a range,
// or the skill's quadratic). At the light's own position L is undefined: 1e-6 keeps it finite.
vec3 pointLight(Surface s, vec3 position, vec3 radiance, float range, vec3 visibility) {
    vec3 toLight = position - s.P;
    float dist = length(toLight);
    vec3 L = toLight / max(dist, 1e-6);
    return lightResponse(s, L) * radiance * attenuation(dist, range) * visibility;
}
