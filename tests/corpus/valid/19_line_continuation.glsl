// Multi-line macros with continuations and a comment inside.
#define SMOOTH_UNION(a, b, k) \
    mix(b, a, clamp(0.5 + 0.5 * ((b) - (a)) / (k), 0.0, 1.0)) - \
    (k) * clamp(0.5 + 0.5 * ((b) - (a)) / (k), 0.0, 1.0) * \
    (1.0 - clamp(0.5 + 0.5 * ((b) - (a)) / (k), 0.0, 1.0)) /* blend */

float circle(vec2 p, float r) { return length(p) - r; }

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    float d = SMOOTH_UNION(circle(p - vec2(0.15 * sin(iTime), 0.0), 0.2),
                           circle(p + vec2(0.15, 0.0), 0.15),
                           0.1);
    vec3 col = d > 0.0 ? vec3(0.9, 0.6, 0.3) : vec3(0.65, 0.85, 1.0);
    col *= 1.0 - exp(-6.0 * abs(d));
    col *= 0.8 + 0.2 * cos(150.0 * d);
    fragColor = vec4(col, 1.0);
}
