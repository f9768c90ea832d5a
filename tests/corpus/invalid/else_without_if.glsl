// else without if
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    fragColor = vec4(0.0);
    else fragColor = vec4(1.0);
}
