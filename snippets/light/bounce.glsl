/* ---
id = "light.bounce"
slot = "light"
summary = "Bounce (indirect) fill: clamped N·L from a horizontal direction, diffuse only, occluded by AO"
provides = ["bounceLight"]
requires = ["Surface"]
sources = ["lighting-model skill, outdoor three-light model (indirect bounce)"]
formula = 'L_o = \rho\, C \operatorname{clamp}(\mathbf{n} \cdot \mathbf{d}, 0, 1)\, \text{occ}'
--- */
// Light the sunlit ground throws back: from the side opposite the sun, horizontal. Unlike the
// back light it does not wrap, so it leaves the side facing the sun unlit.
vec3 bounceLight(Surface s, vec3 dir, vec3 color, float occlusion) {
    return s.diffuseColor * color * clamp(dot(s.N, dir), 0.0, 1.0) * occlusion;
}
