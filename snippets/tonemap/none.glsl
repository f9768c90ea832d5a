/* ---
id = "tonemap.none"
slot = "tonemap"
summary = "No tone mapping: values above 1 clip at output"
provides = ["tonemap"]
requires = []
sources = []
--- */
vec3 tonemap(vec3 color) {
    return color;
}
