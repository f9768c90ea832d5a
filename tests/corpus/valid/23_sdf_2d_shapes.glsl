float sdCircle(in vec2 p, in float r) { return length(p) - r; }

float sdBox(in vec2 p, in vec2 b)
{
    vec2 d = abs(p) - b;
    return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0);
}

float sdSegment(in vec2 p, in vec2 a, in vec2 b)
{
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}

float opRound(float d, float r) { return d - r; }
float opOnion(float d, float r) { return abs(d) - r; }

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec2 m = (2.0 * iMouse.xy - iResolution.xy) / iResolution.y;
    float d = sdCircle(p - vec2(-0.8, 0.0), 0.3);
    d = min(d, opRound(sdBox(p, vec2(0.2, 0.1)), 0.05));
    d = min(d, opOnion(sdSegment(p, vec2(0.5, -0.3), vec2(0.9, 0.3)), 0.02));
    vec3 col = (d > 0.0) ? vec3(0.9, 0.6, 0.3) : vec3(0.65, 0.85, 1.0);
    col = mix(col, vec3(1.0), 1.0 - smoothstep(0.0, 0.01, abs(d)));
    if (iMouse.z > 0.001) {
        col = mix(col, vec3(1.0, 1.0, 0.0), 1.0 - smoothstep(0.0, 0.005, abs(length(p - m) - 0.05)));
    }
    fragColor = vec4(col, 1.0);
}
