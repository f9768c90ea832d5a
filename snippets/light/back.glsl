/* ---
id = "light.back"
slot = "light"
summary = "Back (rim) fill from a horizontal direction, wrapped half-Lambert, occluded by AO"
provides = ["backLight"]
requires = ["Surface"]
sources = ["lighting-model skill, step 8 (back light / rim light)"]
formula = 'L_o = \rho\, C \operatorname{clamp}\left( \frac{\mathbf{n} \cdot \mathbf{d} + 1}{2}, 0, 1 \right) \text{occ}'
--- */
vec3 backLight(Surface s, vec3 dir, vec3 color, float occlusion) {
    float wrapped = clamp(dot(s.N, dir) * 0.5 + 0.5, 0.0, 1.0);
    return s.diffuseColor * color * wrapped * occlusion;
}
