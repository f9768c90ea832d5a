#define PI 3.14159265359
#define TAU (2.0 * PI)
#define SAT(x) clamp(x, 0.0, 1.0)
#define ROT(a) mat2(cos(a), -sin(a), sin(a), cos(a))
#define LAYERS 4
#define RING_DIST(p, r) abs(length(p) - (r))

float ringDist(vec2 p, float r) { return RING_DIST(p, r); }

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    vec3 col = vec3(0.0);
    for (int i = 0; i < LAYERS; i++) {
        vec2 p = ROT(iTime * 0.3 + float(i) * TAU / float(LAYERS)) * uv;
        col += SAT(0.01 / ringDist(p - vec2(0.2, 0.0), 0.1));
    }
#if LAYERS > 2 && defined(PI)
    col *= 0.5;
#else
    col = vec3(1.0, 0.0, 1.0);
#endif
    fragColor = vec4(col, 1.0);
}
