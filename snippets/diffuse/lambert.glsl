/* ---
id = "diffuse.lambert"
slot = "diffuse"
summary = "Lambert: albedo / π times N·L (energy conserving)"
provides = ["diffuse"]
requires = ["PI", "Surface", "Dots"]
sources = ["lighting-model skill, step 2"]
--- */
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * (d.NoL / PI);
}
