/* ---
id = "sdf.smooth_ops"
slot = "sdf"
summary = "Smooth union, intersection and subtraction of two distances with the polynomial smooth minimum of blend radius k > 0 (sharp where |a - b| >= k, within k/4 of sharp inside the blend)"
provides = ["opSmoothUnion", "opSmoothIntersection", "opSmoothSubtraction"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions), smooth operators", "Inigo Quilez, smooth minimum (iquilezles.org/articles/smin)"]
formula = '\operatorname{smin}_k(a, b) = \operatorname{mix}(b, a, h) - k h (1 - h), \quad h = \operatorname{clamp}\left( \tfrac{1}{2} + \tfrac{b - a}{2k}, 0, 1 \right); \quad \operatorname{smax}_k(a, b) = -\operatorname{smin}_k(-a, -b); \quad a \setminus b = \operatorname{smax}_k(a, -b)'
--- */
float opSmoothUnion(float a, float b, float k) {
    // h is the weight of a: 1 where a is the smaller by k or more, 0 where b is.
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

float opSmoothIntersection(float a, float b, float k) {
    // The mirror image: h is the weight of a, 1 where a is the larger by k or more.
    float h = clamp(0.5 - 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) + k * h * (1.0 - h);
}

float opSmoothSubtraction(float a, float b, float k) {
    // a with b carved out: the smooth max of a and the outside of b.
    return opSmoothIntersection(a, -b, k);
}
