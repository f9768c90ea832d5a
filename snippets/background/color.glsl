/* ---
id = "background.color"
slot = "background"
summary = "One flat colour, whatever the environment that surfaces reflect"
provides = ["background"]
requires = []
params = { BACKGROUND_COLOR = { type = "vec3", default = [0.0, 0.0, 0.0] } }
sources = []
formula = 'L_{\text{bg}}(\boldsymbol{\omega}) = C_{\text{bg}}'
--- */
// A studio backdrop: black behind a lit object still lets its surfaces reflect a bright sky.
vec3 background(vec3 rd) {
    return BACKGROUND_COLOR;
}
