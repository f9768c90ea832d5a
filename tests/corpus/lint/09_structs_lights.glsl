// Scene description with structs and arrays: materials in a constant table, an array of
// point and spot lights with physically based falloff, shading a row of spheres and a floor
// by ray casting.

const float PI = 3.14159265;
const int LIGHT_COUNT = 4;
const int OBJECT_COUNT = 4;

struct Material {
    vec3 albedo;
    float shininess;
    float specular;
};

struct PointLight {
    vec3 position;
    vec3 color;
    float intensity;  // candela-like: radiance scale before falloff
    float radius;     // window radius: the light ends smoothly here
};

struct Object {
    vec3 center;
    float radius;
    int material;
};

struct Intersection {
    float t;
    vec3 position;
    vec3 normal;
    int material;
};

const Material MATERIALS[3] = Material[3](
    Material(vec3(0.6, 0.6, 0.6), 8.0, 0.02),
    Material(vec3(0.8, 0.3, 0.2), 64.0, 0.3),
    Material(vec3(0.2, 0.5, 0.8), 256.0, 0.6)
);

const Object OBJECTS[OBJECT_COUNT] = Object[OBJECT_COUNT](
    Object(vec3(-2.4, 0.0, 0.0), 0.8, 1),
    Object(vec3(-0.8, 0.0, 0.0), 0.8, 2),
    Object(vec3(0.8, 0.0, 0.0), 0.8, 1),
    Object(vec3(2.4, 0.0, 0.0), 0.8, 2)
);

// Inverse-square falloff, windowed to reach zero at the light's radius.
float attenuation(float dist, float radius) {
    float ratio = dist / radius;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / max(dist * dist, 0.01);
}

Intersection noHit() {
    return Intersection(1e9, vec3(0.0), vec3(0.0, 1.0, 0.0), -1);
}

Intersection castRay(vec3 ro, vec3 rd) {
    Intersection best = noHit();
    for (int i = 0; i < OBJECT_COUNT; i++) {
        Object obj = OBJECTS[i];
        vec3 oc = ro - obj.center;
        float b = dot(oc, rd);
        float c = dot(oc, oc) - obj.radius * obj.radius;
        float disc = b * b - c;
        if (disc < 0.0) {
            continue;
        }
        float t = -b - sqrt(disc);
        if (t > 1e-3 && t < best.t) {
            vec3 p = ro + rd * t;
            best = Intersection(t, p, (p - obj.center) / obj.radius, obj.material);
        }
    }
    // The floor plane y = -0.8.
    if (rd.y < -1e-4) {
        float t = (-0.8 - ro.y) / rd.y;
        if (t > 1e-3 && t < best.t) {
            best = Intersection(t, ro + rd * t, vec3(0.0, 1.0, 0.0), 0);
        }
    }
    return best;
}

bool occluded(vec3 p, vec3 toLight, float dist) {
    Intersection h = castRay(p, toLight);
    return h.material >= 0 && h.t < dist;
}

vec3 shade(Intersection hit, vec3 viewDir, PointLight lights[LIGHT_COUNT]) {
    Material m = MATERIALS[hit.material];
    vec3 color = m.albedo * vec3(0.03, 0.035, 0.05);
    for (int i = 0; i < LIGHT_COUNT; i++) {
        vec3 toLight = lights[i].position - hit.position;
        float dist = length(toLight);
        vec3 l = toLight / max(dist, 1e-4);
        float ndl = max(dot(hit.normal, l), 0.0);
        if (ndl <= 0.0 || occluded(hit.position + hit.normal * 1e-3, l, dist)) {
            continue;
        }
        vec3 h = normalize(l + viewDir);
        float ndh = max(dot(hit.normal, h), 0.0);
        // Normalised Blinn-Phong so highlights keep their energy as they sharpen.
        float norm = (m.shininess + 8.0) / (8.0 * PI);
        vec3 radiance = lights[i].color * lights[i].intensity
                        * attenuation(dist, lights[i].radius);
        vec3 brdf = m.albedo / PI + m.specular * norm * pow(ndh, m.shininess);
        color += brdf * radiance * ndl;
    }
    return color;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 1.2, 6.0);
    vec3 rd = normalize(vec3(uv.x, uv.y - 0.2, -1.8));

    PointLight lights[LIGHT_COUNT];
    for (int i = 0; i < LIGHT_COUNT; i++) {
        float a = iTime * 0.7 + float(i) * PI * 0.5;
        vec3 tint = 0.5 + 0.5 * cos(vec3(0.0, 2.1, 4.2) + float(i) * 1.7);
        lights[i] = PointLight(vec3(3.0 * cos(a), 1.5, 3.0 * sin(a)), tint, 12.0, 8.0);
    }

    Intersection hit = castRay(ro, rd);
    vec3 color = vec3(0.02, 0.02, 0.03);
    if (hit.material >= 0) {
        color = shade(hit, -rd, lights);
        // A bit of floor reflection for the spheres.
        if (hit.material == 0) {
            vec3 r = reflect(rd, hit.normal);
            Intersection mirror = castRay(hit.position + hit.normal * 1e-3, r);
            if (mirror.material > 0) {
                color += 0.15 * shade(mirror, -r, lights);
            }
        }
    }

    color = color / (1.0 + color);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
