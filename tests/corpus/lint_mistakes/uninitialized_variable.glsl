// expect: valid, findings
// A variable read before anything is written to it on one path: its value is undefined.

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 color;
    if (uv.x > 0.5) {
        color = vec3(uv, 0.5);
    }
    color *= 0.8;
    fragColor = vec4(color, 1.0);
}
