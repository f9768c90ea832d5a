const float weights[5] = float[5](0.227, 0.194, 0.121, 0.054, 0.016);
const vec3 palette[3] = vec3[](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));

float[3] triple(float x)
{
    return float[3](x, x * 2.0, x * 3.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    float sum = 0.0;
    for (int i = 0; i < weights.length(); ++i) {
        sum += weights[i];
    }
    float[3] t = triple(uv.x);
    float b[2];
    b[0] = t[1];
    b[1] = t[2];
    int idx = int(uv.y * 3.0) % 3;
    fragColor = vec4(palette[idx] * sum + b[0] * 0.1, 1.0);
}
