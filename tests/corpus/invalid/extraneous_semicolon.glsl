// a stray semicolon at file scope is an ES error
float k = 1.0;;
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    fragColor = vec4(k);
}
