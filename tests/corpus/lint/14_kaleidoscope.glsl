// A kaleidoscope: the plane folded into mirrored wedges, an iterated fold-and-scale fractal
// inside each wedge, hue cycling and glow. Shows mat2 rotations, domain repetition and
// polar folding.

const float PI = 3.14159265;
const float TAU = 6.28318531;
const int FOLDS = 8;
const int FRACTAL_ITER = 7;

mat2 rotation(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat2(c, s, -s, c);
}

// Mirror the plane into `n` wedges around the origin.
vec2 kaleido(vec2 p, int n) {
    float sector = TAU / float(n);
    float angle = atan(p.y, p.x);
    angle = mod(angle, sector);
    angle = abs(angle - 0.5 * sector);
    return length(p) * vec2(cos(angle), sin(angle));
}

vec3 hueShift(vec3 color, float shift) {
    // Rodrigues rotation around the grey axis.
    const vec3 k = vec3(0.57735);
    float c = cos(shift);
    return color * c + cross(k, color) * sin(shift) + k * dot(k, color) * (1.0 - c);
}

// Iterated fold: returns the trap distance of the orbit to a ring.
float fractal(vec2 p, float time) {
    float trap = 1e3;
    float scale = 1.0;
    mat2 r = rotation(0.3 + 0.1 * sin(time * 0.7));
    for (int i = 0; i < FRACTAL_ITER; i++) {
        p = abs(p) - vec2(0.6, 0.3);
        p = r * p;
        p *= 1.45;
        scale *= 1.45;
        trap = min(trap, abs(length(p) - 0.5) / scale);
    }
    return trap;
}

vec2 repeatGrid(vec2 p, float size) {
    return mod(p + 0.5 * size, size) - 0.5 * size;
}

float glow(float d, float strength, float falloff) {
    return strength / (1.0 + d * falloff);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float time = iTime * 0.5;

    vec2 p = rotation(time * 0.2) * uv;
    p = kaleido(p, FOLDS);
    p -= vec2(0.5 + 0.2 * sin(time), 0.0);

    float d = fractal(p, time);
    vec3 base = vec3(0.9, 0.4, 0.2);
    vec3 color = base * glow(d, 0.02, 200.0);
    color += vec3(0.3, 0.6, 1.0) * exp(-40.0 * d);

    // A repeated grid of dots behind the fractal.
    vec2 cell = repeatGrid(uv * 3.0 + time * 0.3, 1.0);
    float dots = 1.0 - smoothstep(0.06, 0.08, length(cell));
    color += 0.08 * dots * vec3(0.8, 0.9, 1.0);

    color = hueShift(color, time * 0.5);
    float radius = length(uv);
    color *= (1.0 - smoothstep(0.2, 1.6, radius)) * 0.8 + 0.2;
    color = 1.0 - exp(-2.0 * max(color, vec3(0.0)));
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}

// Alternative folds kept for experiments.
vec2 foldSquare(vec2 p) {
    p = abs(p);
    if (p.y > p.x) {
        p = p.yx;
    }
    return p;
}

vec2 foldHex(vec2 p) {
    const vec2 k = vec2(-0.866025404, 0.5);
    p = abs(p);
    p -= 2.0 * min(dot(k, p), 0.0) * k;
    return p;
}

float fractalSquare(vec2 p, float time) {
    float trap = 1e3;
    for (int i = 0; i < FRACTAL_ITER; i++) {
        p = foldSquare(p) - vec2(0.5);
        p = rotation(time * 0.1) * p * 1.5;
        trap = min(trap, length(p));
    }
    return trap;
}
