// expect: valid, findings
// The angle between two normalised vectors by acos(dot(a, b)): rounding can push the dot a
// hair past 1, where acos is undefined (NaN on most GPUs).

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 dir = normalize(vec3(uv, 1.0));
    vec3 sunDir = normalize(vec3(cos(iTime), 0.3, 1.0));
    float angle = acos(dot(dir, sunDir));
    float glow = exp(-angle * 8.0);
    vec3 color = vec3(0.2, 0.4, 0.8) + vec3(1.0, 0.8, 0.5) * glow;
    fragColor = vec4(pow(color / (1.0 + color), vec3(1.0 / 2.2)), 1.0);
}
