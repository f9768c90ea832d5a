/* ---
id = "tonemap.reinhard"
slot = "tonemap"
summary = "Reinhard tone map, c / (c + 1) per channel"
provides = ["tonemap"]
requires = []
sources = ["lighting-model skill, complete code template", "Reinhard et al. 2002"]
formula = 'T(c) = \frac{c}{c + 1}'
--- */
vec3 tonemap(vec3 color) {
    return color / (color + vec3(1.0));
}
