/* ---
id = "tonemap.none"
slot = "tonemap"
summary = "No tone mapping: values above 1 clip at output"
provides = ["tonemap"]
requires = []
sources = []
formula = 'T(c) = c'
--- */
vec3 tonemap(vec3 color) {
    return color;
}
