/* ---
id = "background.gradient"
slot = "background"
summary = "The environment itself, with no sun"
provides = ["background"]
requires = ["env"]
sources = ["lighting-model skill, complete code template (background)"]
formula = 'L_{\text{bg}}(\boldsymbol{\omega}) = L_{\text{env}}(\boldsymbol{\omega})'
--- */
vec3 background(vec3 rd) {
    return environment(rd);
}
