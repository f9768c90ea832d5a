// Texture sampling with iChannel0: blur, lod, texel fetch and size queries.
vec3 blur(vec2 uv)
{
    vec2 px = 1.0 / iChannelResolution[0].xy;
    vec3 acc = vec3(0.0);
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++)
            acc += texture(iChannel0, uv + vec2(x, y) * px).rgb;
    return acc / 9.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    ivec2 size = textureSize(iChannel0, 0);
    vec3 a = blur(uv);
    vec3 b = textureLod(iChannel1, uv, 2.0).rgb;
    vec3 c = texelFetch(iChannel2, ivec2(fragCoord) % size, 0).rgb;
    vec3 d = textureGrad(iChannel3, uv, dFdx(uv), dFdy(uv)).rgb;
    fragColor = vec4(mix(a, b, 0.5) + 0.1 * c + 0.1 * d * fwidth(uv.x), 1.0);
}
