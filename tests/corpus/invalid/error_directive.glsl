// #error in an active branch
#define QUALITY 0
#if QUALITY < 1
#error QUALITY must be at least 1
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    fragColor = vec4(1.0);
}
