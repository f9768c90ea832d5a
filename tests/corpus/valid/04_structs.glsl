struct Material {
    vec3 albedo;
    float roughness;
    float metallic;
};

struct Light { vec3 dir; vec3 color; } sun;

struct Hit {
    float t;
    vec3 n;
    Material mat;
};

Material makeMaterial(vec3 c, float r)
{
    return Material(c, r, 0.0);
}

vec3 shade(Hit h, Light l)
{
    float ndl = max(dot(h.n, l.dir), 0.0);
    return h.mat.albedo * l.color * ndl;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    sun = Light(normalize(vec3(1.0, 1.0, 0.5)), vec3(1.0, 0.95, 0.9));
    Hit h;
    h.t = 1.0;
    h.n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    h.mat = makeMaterial(vec3(0.8, 0.2, 0.2), 0.5);
    fragColor = vec4(shade(h, sun), 1.0);
}
