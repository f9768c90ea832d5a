// 2D checkerboard with integer math and the ternary operator.
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    ivec2 cell = ivec2(floor(fragCoord / 16.0));
    bool odd = ((cell.x + cell.y) & 1) == 1;
    vec3 col = odd ? vec3(0.9) : vec3(0.1);
    col *= (cell.x % 4 == 0) ? 0.8 : 1.0;
    fragColor = vec4(col, 1.0);
}
