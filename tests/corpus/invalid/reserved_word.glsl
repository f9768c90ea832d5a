// a reserved word used as a name
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float input = 1.0;
    fragColor = vec4(input);
}
