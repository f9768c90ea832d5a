// A grid of spheres under two lights, shaded with a Cook-Torrance BRDF: GGX distribution,
// height-correlated Smith visibility and Schlick's Fresnel on the half vector, plus a
// Lambert diffuse lobe weighted by what the specular did not reflect.

const float PI = 3.14159265359;
const int ROWS = 4;
const int COLUMNS = 5;

struct Material {
    vec3 baseColor;
    float roughness;  // perceptual, 0..1
    float metallic;
};

struct Light {
    vec3 direction;  // towards the light
    vec3 radiance;
};

float distributionGGX(float NoH, float alpha) {
    float a2 = alpha * alpha;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

// Smith-GGX visibility, height correlated: G / (4 NoL NoV) in one term.
float visibilitySmithGGX(float NoV, float NoL, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(lambdaV + lambdaL, 1e-5);
}

vec3 fresnelSchlick(float VoH, vec3 f0) {
    float f = pow(clamp(1.0 - VoH, 0.0, 1.0), 5.0);
    return f0 + (1.0 - f0) * f;
}

vec3 brdf(Material m, vec3 n, vec3 v, vec3 l) {
    vec3 h = normalize(v + l);
    float NoV = max(dot(n, v), 1e-4);
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float VoH = clamp(dot(v, h), 0.0, 1.0);

    float roughness = clamp(m.roughness, 0.045, 1.0);
    float alpha = roughness * roughness;
    vec3 f0 = mix(vec3(0.04), m.baseColor, m.metallic);

    vec3 F = fresnelSchlick(VoH, f0);
    float D = distributionGGX(NoH, alpha);
    float V = visibilitySmithGGX(NoV, NoL, alpha);
    vec3 specular = D * V * F;

    vec3 kd = (vec3(1.0) - F) * (1.0 - m.metallic);
    vec3 diffuse = kd * m.baseColor / PI;
    return (diffuse + specular) * NoL;
}

vec3 environment(vec3 dir) {
    float up = clamp(0.5 + 0.5 * dir.y, 0.0, 1.0);
    return mix(vec3(0.05, 0.045, 0.04), vec3(0.35, 0.45, 0.6), up);
}

// Ray-sphere intersection; returns the nearest positive t or -1.
float intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius) {
    vec3 oc = ro - center;
    float b = dot(oc, rd);
    float c = dot(oc, oc) - radius * radius;
    float disc = b * b - c;
    if (disc < 0.0) {
        return -1.0;
    }
    float t = -b - sqrt(disc);
    return t > 0.0 ? t : -1.0;
}

vec3 acesFilm(vec3 x) {
    const float a = 2.51;
    const float b = 0.03;
    const float c = 2.43;
    const float d = 0.59;
    const float e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.0, 9.0);
    vec3 rd = normalize(vec3(uv, -2.2));

    Light lights[2];
    float orbit = 0.4 * iTime;
    lights[0] = Light(normalize(vec3(cos(orbit), 0.8, sin(orbit) + 1.5)), vec3(3.0, 2.85, 2.6));
    lights[1] = Light(normalize(vec3(-0.7, -0.2, 0.6)), vec3(0.4, 0.5, 0.7));

    float nearest = 1e9;
    vec3 hitNormal = vec3(0.0, 0.0, 1.0);
    Material hitMaterial = Material(vec3(0.0), 1.0, 0.0);
    for (int row = 0; row < ROWS; row++) {
        for (int col = 0; col < COLUMNS; col++) {
            vec3 center = vec3(float(col - COLUMNS / 2) * 1.15, float(row) * 1.15 - 1.7, 0.0);
            float t = intersectSphere(ro, rd, center, 0.5);
            if (t > 0.0 && t < nearest) {
                nearest = t;
                hitNormal = normalize(ro + rd * t - center);
                float roughness = (float(col) + 0.5) / float(COLUMNS);
                float metallic = float(row) / float(ROWS - 1);
                vec3 base = mix(vec3(0.9, 0.1, 0.1), vec3(1.0, 0.78, 0.34), metallic);
                hitMaterial = Material(base, roughness, metallic);
            }
        }
    }

    vec3 color;
    if (nearest < 1e9) {
        vec3 v = -rd;
        color = vec3(0.0);
        for (int i = 0; i < 2; i++) {
            color += brdf(hitMaterial, hitNormal, v, lights[i].direction) * lights[i].radiance;
        }
        vec3 f0 = mix(vec3(0.04), hitMaterial.baseColor, hitMaterial.metallic);
        vec3 ambientDiffuse = hitMaterial.baseColor * (1.0 - hitMaterial.metallic);
        color += 0.3 * environment(hitNormal) * ambientDiffuse;
        vec3 r = reflect(rd, hitNormal);
        float NoV = clamp(dot(hitNormal, v), 0.0, 1.0);
        vec3 envSpec = environment(r) * fresnelSchlick(NoV, f0);
        color += envSpec * (1.0 - 0.7 * hitMaterial.roughness);
    } else {
        color = environment(rd) * 0.5;
    }

    color = acesFilm(color * 1.2);
    fragColor = vec4(linearToSrgb(color), 1.0);
}
