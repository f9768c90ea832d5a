#define PI 3.14159265359
#define MIN_ROUGHNESS 0.045

float D_GGX(float NoH, float a)
{
    float a2 = a * a;
    float f = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (PI * f * f);
}

float V_SmithGGXCorrelated(float NoV, float NoL, float a)
{
    float a2 = a * a;
    float GGXL = NoV * sqrt((-NoL * a2 + NoL) * NoL + a2);
    float GGXV = NoL * sqrt((-NoV * a2 + NoV) * NoV + a2);
    return 0.5 / (GGXV + GGXL);
}

vec3 F_Schlick(float VoH, vec3 f0)
{
    float f = pow(1.0 - VoH, 5.0);
    return f + f0 * (1.0 - f);
}

vec3 brdf(vec3 n, vec3 v, vec3 l, vec3 base, float roughness, float metallic)
{
    vec3 h = normalize(v + l);
    float NoV = abs(dot(n, v)) + 1e-5;
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float LoH = clamp(dot(l, h), 0.0, 1.0);
    float r = max(roughness, MIN_ROUGHNESS);
    float a = r * r;
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 Fr = D_GGX(NoH, a) * V_SmithGGXCorrelated(NoV, NoL, a) * F_Schlick(LoH, f0);
    vec3 Fd = base * (1.0 - metallic) / PI;
    return (Fr + Fd) * NoL;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float r2 = dot(uv, uv);
    if (r2 > 1.0) { fragColor = vec4(0.02, 0.02, 0.03, 1.0); return; }
    vec3 n = vec3(uv, sqrt(1.0 - r2));
    vec3 l = normalize(vec3(cos(iTime), 0.8, sin(iTime) + 1.0));
    vec3 c = brdf(n, vec3(0, 0, 1), l, vec3(0.9, 0.6, 0.2), fragCoord.x / iResolution.x, 1.0) * 3.0;
    c = c / (1.0 + c);
    fragColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
