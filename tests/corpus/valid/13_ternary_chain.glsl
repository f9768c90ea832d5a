float band(float x)
{
    return x < 0.25 ? 0.0 : x < 0.5 ? 0.33 : x < 0.75 ? 0.66 : 1.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    bool inside = uv.x > 0.1 && uv.x < 0.9 || uv.y > 0.5 ^^ uv.y > 0.8;
    float v = inside ? band(uv.x) : 1.0 - band(uv.y);
    v = !inside ? -v + 1.0 : +v;
    fragColor = vec4(vec3(v), 1.0);
}
