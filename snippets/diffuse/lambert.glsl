/* ---
id = "diffuse.lambert"
slot = "diffuse"
summary = "Lambert diffuse BRDF, albedo / π (energy conserving)"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
sources = ["lighting-model skill, step 2"]
--- */
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * (1.0 / PI);
}
