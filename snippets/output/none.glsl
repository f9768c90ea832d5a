/* ---
id = "output.none"
slot = "output"
summary = "No transfer function: the linear colour as it is (for a buffer another pass reads)"
provides = ["outputTransfer"]
requires = []
sources = []
formula = 'V(c) = c'
--- */
// For a buffer that another pass reads as linear light, or a runner that encodes the
// picture itself. On a plain display the picture looks dark: gamma22 or srgb is for that.
vec3 outputTransfer(vec3 color) {
    return color;
}
