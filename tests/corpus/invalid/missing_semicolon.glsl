// missing semicolon after a declaration
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec3 col = vec3(1.0)
    fragColor = vec4(col, 1.0);
}
