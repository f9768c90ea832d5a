// Hexagonal tiling; vec4 return packs the cell id and local coordinates.
const vec2 s = vec2(1.0, 1.7320508);

float hexDist(vec2 p)
{
    p = abs(p);
    return max(dot(p, s * 0.5), p.x);
}

vec4 hexCoords(vec2 p)
{
    vec4 hc = floor(vec4(p, p - vec2(0.5, 1.0)) / s.xyxy) + 0.5;
    vec4 h = vec4(p - hc.xy * s, p - (hc.zw + 0.5) * s);
    return dot(h.xy, h.xy) < dot(h.zw, h.zw)
        ? vec4(h.xy, hc.xy)
        : vec4(h.zw, hc.zw + 0.5);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y * 8.0;
    vec4 h = hexCoords(uv + iTime * 0.2);
    float edge = smoothstep(0.45, 0.5, hexDist(h.xy));
    vec3 col = 0.5 + 0.5 * sin(h.zwz * vec3(0.7, 1.3, 2.1));
    fragColor = vec4(mix(col, vec3(0.05), edge), 1.0);
}
