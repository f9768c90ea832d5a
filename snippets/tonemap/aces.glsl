/* ---
id = "tonemap.aces"
slot = "tonemap"
summary = "ACES filmic curve, Narkowicz's fit"
provides = ["tonemap"]
requires = []
sources = ["lighting-model skill, post-processing integration", "Narkowicz 2015"]
formula = 'T(c) = \operatorname{clamp}\left( \frac{c\, (2.51\, c + 0.03)}{c\, (2.43\, c + 0.59) + 0.14},\ 0,\ 1 \right)'
--- */
vec3 tonemap(vec3 color) {
    vec3 mapped = (color * (2.51 * color + 0.03)) / (color * (2.43 * color + 0.59) + 0.14);
    return clamp(mapped, 0.0, 1.0);
}
