// for loop with a missing clause separator
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float s = 0.0;
    for (int i = 0; i < 4 i++) s += 1.0;
    fragColor = vec4(s);
}
