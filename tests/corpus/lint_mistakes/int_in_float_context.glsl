// expect: invalid
// Integer literals where floats are needed: ES has no implicit int-to-float conversion.

float vignette(vec2 uv) {
    vec2 d = uv - 0.5;
    return 1 - dot(d, d) * 2;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 color = vec3(uv, 0.5) * vignette(uv);
    fragColor = vec4(color, 1);
}
