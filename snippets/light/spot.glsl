/* ---
id = "light.spot"
slot = "light"
summary = "Spot light: a point light shining into a cone, full inside the inner angle and none outside the outer"
provides = ["spotLight"]
requires = ["Surface", "lightResponse", "attenuation", "spotCone"]
sources = ["Filament PBR notes, 5.2.2.2 (spot lights)", "Lagarde & de Rousiers 2014, Moving Frostbite to PBR, 4.5 (punctual lights)"]
formula = 'L_o = R(\mathbf{l})\, L_{\text{light}}\, A(d, r)\, C(-\mathbf{l} \cdot \mathbf{a})\, S'
--- */
// A point light (light.point) times the cone's falloff C (light.spot_cone) along the angle
// between the spot's axis `axis` (the way it shines) and the ray from the light to the point.
// `cosCone` holds the cosines of the outer and inner half-angles.
vec3 spotLight(Surface s, vec3 position, vec3 axis, vec2 cosCone, vec3 radiance, float range,
               vec3 visibility) {
    vec3 toLight = position - s.P;
    float dist = length(toLight);
    vec3 L = toLight / max(dist, 1e-6);
    float cone = spotCone(dot(-L, axis), cosCone.x, cosCone.y);
    return lightResponse(s, L) * radiance * (attenuation(dist, range) * cone) * visibility;
}
