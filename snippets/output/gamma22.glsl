/* ---
id = "output.gamma22"
slot = "output"
summary = "Display encoding with a pure 2.2 gamma"
provides = ["outputTransfer"]
requires = []
sources = ["lighting-model skill, complete code template"]
formula = 'V(c) = \max(c, 0)^{1/2.2}'
--- */
// max() keeps pow defined: its base must not be negative.
vec3 outputTransfer(vec3 color) {
    return pow(max(color, 0.0), vec3(1.0 / 2.2));
}
