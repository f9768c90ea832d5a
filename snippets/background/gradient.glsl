/* ---
id = "background.gradient"
slot = "background"
summary = "The environment itself, with no sun"
provides = ["background"]
requires = ["env"]
sources = ["lighting-model skill, complete code template (background)"]
--- */
vec3 background(vec3 rd) {
    return environment(rd);
}
