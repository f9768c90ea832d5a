/* ---
id = "output.srgb"
slot = "output"
summary = "Exact sRGB transfer function (linear toe below 0.0031308)"
provides = ["outputTransfer"]
requires = []
sources = ["IEC 61966-2-1"]
formula = 'V(c) = \begin{cases} 12.92\, c & c < 0.0031308 \\ 1.055\, c^{1/2.4} - 0.055 & c \ge 0.0031308 \end{cases}, \quad c \ge 0'
--- */
vec3 outputTransfer(vec3 color) {
    vec3 c = max(color, 0.0);
    vec3 lo = 12.92 * c;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}
