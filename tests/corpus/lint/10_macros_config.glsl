// A configurable raymarcher: quality switches with #if/#ifdef, function-like macros for
// small helpers, a macro that builds repeated code and a debug view chosen at compile time.

#define QUALITY 2          // 1 = fast, 2 = balanced, 3 = high
#define SHOW_STEPS 0       // 1 shows the step count instead of the shading
#define USE_SOFT_SHADOWS

#if QUALITY >= 3
    #define MAX_STEPS 256
    #define SHADOW_STEPS 96
#elif QUALITY == 2
    #define MAX_STEPS 128
    #define SHADOW_STEPS 48
#else
    #define MAX_STEPS 64
    #define SHADOW_STEPS 16
#endif

#define MAX_DIST 30.0
#define EPSILON 0.001
#define PI 3.14159265
#define SATURATE(x) clamp((x), 0.0, 1.0)
#define SQ(x) ((x) * (x))
#define ROT(a) mat2(cos(a), -sin(a), sin(a), cos(a))
#define MIN3(a, b, c) min((a), min((b), (c)))

float sdBox(vec3 p, vec3 b) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r) {
    vec3 pa = p - a;
    vec3 ba = b - a;
    float h = SATURATE(dot(pa, ba) / dot(ba, ba));
    return length(pa - ba * h) - r;
}

// Infinite repetition of space along x and z, every `period` units.
vec3 repeatXZ(vec3 p, float period) {
    p.xz = mod(p.xz + 0.5 * period, period) - 0.5 * period;
    return p;
}

float map(vec3 p) {
    float ground = p.y + 1.0;
    vec3 q = repeatXZ(p, 4.0);
    q.xz *= ROT(0.3 * iTime);
    float pillar = sdBox(q, vec3(0.4, 1.5, 0.4)) - 0.05;
    float bar = sdCapsule(q, vec3(-1.2, 0.6, 0.0), vec3(1.2, 0.6, 0.0), 0.12);
    float ring = length(vec2(length(q.xz) - 0.9, q.y + 0.4)) - 0.1;
    return MIN3(ground, pillar, min(bar, ring));
}

vec3 normalAt(vec3 p) {
    vec2 e = vec2(EPSILON, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float march(vec3 ro, vec3 rd, out int steps) {
    float t = 0.0;
    steps = 0;
    for (int i = 0; i < MAX_STEPS; i++) {
        steps = i;
        float d = map(ro + rd * t);
        if (d < EPSILON * (1.0 + t)) {
            return t;
        }
        t += d;
        if (t > MAX_DIST) {
            break;
        }
    }
    return MAX_DIST;
}

float shadow(vec3 ro, vec3 rd) {
#ifdef USE_SOFT_SHADOWS
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < SHADOW_STEPS; i++) {
        float h = map(ro + rd * t);
        res = min(res, 8.0 * h / t);
        t += clamp(h, 0.02, 0.5);
        if (res < 0.001 || t > MAX_DIST) {
            break;
        }
    }
    return SATURATE(res);
#else
    int unused;
    return march(ro, rd, unused) < MAX_DIST ? 0.0 : 1.0;
#endif
}

vec3 heatmap(float x) {
    x = SATURATE(x);
    return vec3(SATURATE(2.0 * x), SATURATE(2.0 * x - 0.5), SATURATE(4.0 * x - 3.0));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(2.0, 1.5, -4.0 + iTime);
    vec3 rd = normalize(vec3(uv, 1.5));
    rd.yz *= ROT(0.25);

    int steps;
    float t = march(ro, rd, steps);

#if SHOW_STEPS
    vec3 color = heatmap(float(steps) / float(MAX_STEPS));
#else
    vec3 color = vec3(0.6, 0.7, 0.8);
    if (t < MAX_DIST) {
        vec3 p = ro + rd * t;
        vec3 n = normalAt(p);
        vec3 l = normalize(vec3(0.5, 0.8, -0.3));
        float ndl = max(dot(n, l), 0.0);
        float sh = ndl > 0.0 ? shadow(p + n * 0.01, l) : 0.0;
        vec3 base = mix(vec3(0.8, 0.75, 0.7), vec3(0.3, 0.35, 0.4), step(p.y, -0.99));
        color = base * (ndl * sh * vec3(1.0, 0.95, 0.85) + 0.15 * SATURATE(0.5 + 0.5 * n.y));
        color = mix(color, vec3(0.6, 0.7, 0.8), 1.0 - exp(-SQ(t / MAX_DIST) * 3.0));
    }
    color = pow(color, vec3(1.0 / 2.2));
#endif

    fragColor = vec4(color, 1.0);
}
