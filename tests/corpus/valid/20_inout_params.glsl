void rotate(inout vec2 p, float a)
{
    float c = cos(a), s = sin(a);
    p = mat2(c, s, -s, c) * p;
}

void split(in vec3 v, out float x, out vec2 yz)
{
    x = v.x;
    yz = v.yz;
}

float accumulate(const in float values[4])
{
    float total = 0.0;
    for (int i = 0; i < 4; i++) total += values[i];
    return total;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = fragCoord / iResolution.xy - 0.5;
    rotate(p, iTime);
    float x;
    vec2 yz;
    split(vec3(p, 0.5), x, yz);
    float vals[4] = float[4](x, yz.x, yz.y, 0.25);
    fragColor = vec4(vec3(accumulate(vals) * 0.5), 1.0);
}
