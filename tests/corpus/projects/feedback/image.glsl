// Image: the trail of Buffer A over a picture on channel 1.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 ground = texture(iChannel1, uv * 2.0).rgb * 0.5;
    vec3 trail = texture(iChannel0, uv).rgb;
    fragColor = vec4(ground + trail, 1.0);
}
