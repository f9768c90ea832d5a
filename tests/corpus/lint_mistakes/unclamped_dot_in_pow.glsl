// expect: valid, findings
// A Phong highlight whose base may be negative: pow(x, y) is undefined for x < 0, and
// dot(r, v) is negative whenever the reflection points away from the viewer.

float sphere(vec3 ro, vec3 rd, float r) {
    float b = dot(ro, rd);
    float c = dot(ro, ro) - r * r;
    float h = b * b - c;
    return h < 0.0 ? -1.0 : -b - sqrt(h);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.0, 3.0);
    vec3 rd = normalize(vec3(uv, -1.5));
    float t = sphere(ro, rd, 1.0);
    vec3 color = vec3(0.05);
    if (t > 0.0) {
        vec3 n = normalize(ro + rd * t);
        vec3 l = normalize(vec3(cos(iTime), 1.0, 1.0));
        vec3 v = -rd;
        vec3 r = reflect(-l, n);
        float diffuse = max(dot(n, l), 0.0);
        float specular = pow(dot(r, v), 32.0);
        color = vec3(0.8, 0.3, 0.2) * diffuse + vec3(specular);
    }
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
