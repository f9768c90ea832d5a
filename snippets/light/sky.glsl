/* ---
id = "light.sky"
slot = "light"
summary = "Sky fill: the cheap hemisphere integral 0.5 + 0.5·N.y, diffuse only, occluded by AO"
provides = ["skyLight"]
requires = ["Surface"]
sources = ["lighting-model skill, step 8 (sky light)"]
formula = 'L_o = \rho\, C\, \frac{1 + n_y}{2}\, \text{occ}'
--- */
vec3 skyLight(Surface s, vec3 color, float occlusion) {
    float hemisphere = 0.5 + 0.5 * s.N.y;
    return s.diffuseColor * color * hemisphere * occlusion;
}
