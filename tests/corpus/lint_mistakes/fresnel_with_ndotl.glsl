// expect: valid, findings
// Schlick's Fresnel fed with N.L instead of the view angle (V.H, or N.V for a reflection):
// the rim brightens where the light grazes, not where the viewer does.

const float PI = 3.14159265;

vec3 fresnelSchlick(float cosTheta, vec3 f0) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float r2 = dot(uv, uv);
    vec3 color = vec3(0.02);
    if (r2 < 1.0) {
        vec3 n = vec3(uv, sqrt(1.0 - r2));
        vec3 v = vec3(0.0, 0.0, 1.0);
        vec3 l = normalize(vec3(cos(iTime), 0.6, sin(iTime)));
        vec3 h = normalize(l + v);
        float NdotL = max(dot(n, l), 0.0);
        float NdotH = max(dot(n, h), 0.0);
        vec3 F = fresnelSchlick(NdotL, vec3(0.04));
        float spec = pow(NdotH, 64.0) * (64.0 + 8.0) / (8.0 * PI);
        color = vec3(0.5, 0.5, 0.55) / PI * NdotL + F * spec * NdotL;
    }
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
