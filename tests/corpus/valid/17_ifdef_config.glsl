// Configuration knobs with nested conditionals and #undef.
#define QUALITY 2
#define USE_AA
#define DEBUG

#ifdef DEBUG
#undef DEBUG
#endif

#if QUALITY >= 2
    #define SAMPLES 4
#elif QUALITY == 1
    #define SAMPLES 2
#else
    #define SAMPLES 1
#endif

#ifndef SAMPLES
#error SAMPLES must be defined
#endif

vec3 render(vec2 p)
{
    return vec3(step(0.5, fract(p.x * 8.0)) * step(0.5, fract(p.y * 8.0)));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec3 col = vec3(0.0);
#ifdef USE_AA
    for (int i = 0; i < SAMPLES; i++) {
        vec2 o = vec2(float(i % 2), float(i / 2)) / 2.0;
        col += render((fragCoord + o) / iResolution.xy);
    }
    col /= float(SAMPLES);
#else
    col = render(fragCoord / iResolution.xy);
#endif
#if defined(DEBUG) || !defined(USE_AA)
    col = vec3(1.0, 0.0, 0.0);
#endif
    fragColor = vec4(col, 1.0);
}
