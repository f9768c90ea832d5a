// expect: valid, findings
// smoothstep with edge0 > edge1 to get a falling edge: undefined in GLSL (it happens to work
// on many GPUs); 1.0 - smoothstep(lo, hi, x) says the same portably.

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float d = length(uv) - 0.5;
    float disc = smoothstep(0.01, 0.0, d);
    vec3 color = mix(vec3(0.1, 0.1, 0.15), vec3(1.0, 0.8, 0.3), disc);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
