// Boolean vectors, relational builtins and packing functions.
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    bvec2 gt = greaterThan(uv, vec2(0.5));
    bvec2 both = bvec2(all(gt), any(gt));
    bool none = !any(notEqual(uv, uv));
    uint packed = packHalf2x16(uv);
    vec2 back = unpackHalf2x16(packed);
    int bits = floatBitsToInt(back.x);
    float again = intBitsToFloat(bits);
    uvec2 u = uvec2(3u, 5u) * 2u;
    ivec3 iv = ivec3(1, -2, 3) / 2;
    float isBad = float(isnan(again) || isinf(again));
    fragColor = vec4(both.x ? 1.0 : 0.0, none ? again : 0.0, float(u.x + uint(iv.z)) * 0.01, 1.0 - isBad);
}
