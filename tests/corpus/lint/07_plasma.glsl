// An old-school plasma: a sum of sines over distorted coordinates, turned into colour by a
// cosine palette, with a scanline and a soft CRT vignette.

const float PI = 3.14159265;
const float TAU = 6.28318531;

// Cosine palette: a + b * cos(2 pi (c t + d)).
vec3 palette(float t, vec3 a, vec3 b, vec3 c, vec3 d) {
    return a + b * cos(TAU * (c * t + d));
}

float wave(vec2 p, vec2 dir, float freq, float speed, float time) {
    return sin(dot(p, dir) * freq + time * speed);
}

float plasma(vec2 p, float time) {
    float v = 0.0;
    v += wave(p, vec2(1.0, 0.0), 3.0, 1.0, time);
    v += wave(p, vec2(0.0, 1.0), 2.6, 1.3, time);
    v += wave(p, normalize(vec2(1.0, 1.0)), 3.4, 0.7, time);
    vec2 c = p + 0.6 * vec2(sin(time * 0.33), cos(time * 0.5));
    v += sin(sqrt(dot(c, c) * 16.0 + 1.0) + time);
    return v * 0.25;
}

vec2 swirl(vec2 p, float amount) {
    float r = length(p);
    float a = amount * exp(-r * 1.5);
    float c = cos(a);
    float s = sin(a);
    return mat2(c, s, -s, c) * p;
}

float scanline(vec2 fragCoord, float time) {
    float line = 0.5 + 0.5 * sin(fragCoord.y * PI * 0.5 + time * 4.0);
    return 0.9 + 0.1 * line;
}

vec2 barrel(vec2 uv, float k) {
    float r2 = dot(uv, uv);
    return uv * (1.0 + k * r2);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec2 centered = uv * 2.0 - 1.0;
    centered = barrel(centered, 0.08);
    vec2 p = centered * vec2(iResolution.x / iResolution.y, 1.0);

    float time = iTime * 0.8;
    vec2 q = swirl(p, 2.0 * sin(time * 0.3));
    float v = plasma(q * 1.5, time);

    vec3 color = palette(v + 0.1 * time,
                         vec3(0.5, 0.5, 0.5),
                         vec3(0.5, 0.5, 0.5),
                         vec3(1.0, 1.0, 1.0),
                         vec3(0.0, 0.33, 0.67));

    // A second, slower layer adds depth where the two agree.
    float v2 = plasma(p * 0.7 + 3.0, time * 0.5);
    vec3 color2 = palette(v2, vec3(0.5), vec3(0.5), vec3(1.0, 0.7, 0.4), vec3(0.0, 0.15, 0.2));
    color = mix(color, color2, 0.35 + 0.15 * sin(time));

    color *= scanline(fragCoord, iTime);

    // Outside the curved screen is black; the edge fades over a few pixels.
    vec2 edge = 1.0 - smoothstep(vec2(0.97), vec2(1.0), abs(centered));
    color *= edge.x * edge.y;

    float vignette = 1.0 - 0.35 * dot(centered * 0.7, centered * 0.7);
    color *= clamp(vignette, 0.0, 1.0);

    fragColor = vec4(clamp(color, 0.0, 1.0), 1.0);
}

// Palettes kept for experimenting; each is a named set of palette coefficients.
vec3 paletteSunset(float t) {
    return palette(t, vec3(0.5, 0.3, 0.2), vec3(0.5, 0.3, 0.2), vec3(1.0), vec3(0.0, 0.1, 0.2));
}

vec3 paletteOcean(float t) {
    return palette(t, vec3(0.2, 0.4, 0.5), vec3(0.2, 0.3, 0.4), vec3(1.0), vec3(0.3, 0.2, 0.1));
}

vec3 paletteAcid(float t) {
    return palette(t, vec3(0.5), vec3(0.5), vec3(2.0, 1.0, 0.0), vec3(0.5, 0.2, 0.25));
}

float plasmaFast(vec2 p, float time) {
    return 0.5 * (sin(p.x * 3.0 + time) + sin(p.y * 2.0 - time));
}

vec3 plasmaPreview(vec2 p, float time) {
    float v = plasmaFast(p, time);
    return mix(paletteSunset(v), paletteOcean(v), 0.5 + 0.5 * sin(time));
}

vec3 plasmaAcidPreview(vec2 p, float time) {
    return paletteAcid(plasmaFast(p * 2.0, time));
}
