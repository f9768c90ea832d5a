// expect: invalid
// Ported from WebGL 1: texture2D does not exist in GLSL ES 3.00 (texture() replaces it).

vec3 blur3(vec2 uv, vec2 texel) {
    vec3 sum = vec3(0.0);
    for (int i = -1; i <= 1; i++) {
        sum += texture2D(iChannel0, uv + vec2(float(i), 0.0) * texel).rgb;
    }
    return sum / 3.0;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 color = blur3(uv, 1.0 / iResolution.xy);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
