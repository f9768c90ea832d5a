// expect: valid, findings
// Lighting computed in linear units and written straight out: no tone mapping, no
// conversion to sRGB, so the image looks too dark and too contrasty.

const float PI = 3.14159265;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float r2 = dot(uv, uv);
    vec3 color = vec3(0.0);
    if (r2 < 1.0) {
        vec3 n = vec3(uv, sqrt(1.0 - r2));
        vec3 l = normalize(vec3(0.5, 0.7, 0.5));
        vec3 albedo = vec3(0.7, 0.5, 0.3);
        float ndl = max(dot(n, l), 0.0);
        vec3 radiance = vec3(3.0);
        color = albedo / PI * radiance * ndl + albedo * 0.03;
    }
    fragColor = vec4(color, 1.0);
}
