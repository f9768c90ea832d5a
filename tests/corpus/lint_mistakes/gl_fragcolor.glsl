// expect: invalid
// Writing gl_FragColor instead of the out parameter of mainImage (removed in ES 3.00).

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float d = length(uv - 0.5);
    gl_FragColor = vec4(vec3(1.0 - smoothstep(0.29, 0.3, d)), 1.0);
}
