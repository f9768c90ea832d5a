// Buffer A: a trail. Each frame keeps 95 % of the last frame's picture (its own channel 0)
// and adds a dot that circles the centre, so the picture is the history of the dot.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 last = texture(iChannel0, uv).rgb * 0.95;
    vec2 dot_at = 0.5 + 0.3 * vec2(cos(iTime * 3.0), sin(iTime * 3.0));
    float d = length((uv - dot_at) * iResolution.xy / iResolution.y);
    fragColor = vec4(last + tint() * smoothstep(0.06, 0.03, d), 1.0);
}
