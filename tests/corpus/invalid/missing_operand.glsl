// an operator missing its operand
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float a = 1.0 * ;
    fragColor = vec4(a);
}
