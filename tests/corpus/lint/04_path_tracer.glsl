// A tiny path tracer: spheres in a box, cosine-weighted bounces, next-event estimation
// towards a spherical lamp, Russian roulette after a few bounces. One frame's estimate
// (a buffer would accumulate frames; the seed already depends on iFrame for that).

const float PI = 3.14159265;
const float INF = 1e20;
const int SAMPLES = 4;
const int BOUNCES = 5;

struct Ray {
    vec3 origin;
    vec3 dir;
};

struct Sphere {
    vec3 center;
    float radius;
    vec3 albedo;
    vec3 emission;
};

const int SPHERE_COUNT = 7;
const Sphere SPHERES[SPHERE_COUNT] = Sphere[SPHERE_COUNT](
    Sphere(vec3(-1001.0, 0.0, 0.0), 1000.0, vec3(0.75, 0.25, 0.25), vec3(0.0)),
    Sphere(vec3(1001.0, 0.0, 0.0), 1000.0, vec3(0.25, 0.25, 0.75), vec3(0.0)),
    Sphere(vec3(0.0, -1001.0, 0.0), 1000.0, vec3(0.75), vec3(0.0)),
    Sphere(vec3(0.0, 1001.0, 0.0), 1000.0, vec3(0.75), vec3(0.0)),
    Sphere(vec3(0.0, 0.0, -1002.0), 1000.0, vec3(0.75), vec3(0.0)),
    Sphere(vec3(-0.45, -0.6, -0.6), 0.4, vec3(0.9, 0.9, 0.6), vec3(0.0)),
    Sphere(vec3(0.0, 0.95, -0.5), 0.12, vec3(0.0), vec3(40.0, 36.0, 30.0))
);
const int LAMP = 6;

// PCG-style integer hash: good enough decorrelation per pixel and frame.
uint hashUint(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float random(inout uint seed) {
    seed = hashUint(seed);
    return float(seed) / 4294967295.0;
}

float intersect(Ray ray, Sphere s) {
    vec3 oc = ray.origin - s.center;
    float b = dot(oc, ray.dir);
    float c = dot(oc, oc) - s.radius * s.radius;
    float disc = b * b - c;
    if (disc < 0.0) {
        return INF;
    }
    float root = sqrt(disc);
    float t = -b - root;
    if (t > 1e-4) {
        return t;
    }
    t = -b + root;
    return t > 1e-4 ? t : INF;
}

bool trace(Ray ray, out float tHit, out int index) {
    tHit = INF;
    index = -1;
    for (int i = 0; i < SPHERE_COUNT; i++) {
        float t = intersect(ray, SPHERES[i]);
        if (t < tHit) {
            tHit = t;
            index = i;
        }
    }
    return index >= 0;
}

// Orthonormal basis around n (Duff et al.'s branchless construction).
mat3 basis(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

vec3 cosineHemisphere(vec3 n, inout uint seed) {
    float u1 = random(seed);
    float u2 = random(seed);
    float r = sqrt(u1);
    float phi = 2.0 * PI * u2;
    vec3 local = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u1)));
    return normalize(basis(n) * local);
}

// Direct light from the spherical lamp, sampled by solid angle of its cone.
vec3 sampleLamp(vec3 p, vec3 n, vec3 albedo, inout uint seed) {
    Sphere lamp = SPHERES[LAMP];
    vec3 toCenter = lamp.center - p;
    float dist2 = dot(toCenter, toCenter);
    float sinMax2 = lamp.radius * lamp.radius / dist2;
    float cosMax = sqrt(max(0.0, 1.0 - sinMax2));
    float u1 = random(seed);
    float u2 = random(seed);
    float cosTheta = 1.0 - u1 * (1.0 - cosMax);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * PI * u2;
    vec3 w = normalize(toCenter);
    vec3 dir = basis(w) * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
    float ndl = dot(n, dir);
    if (ndl <= 0.0) {
        return vec3(0.0);
    }
    float tHit;
    int index;
    if (!trace(Ray(p, dir), tHit, index) || index != LAMP) {
        return vec3(0.0);
    }
    float solidAngle = 2.0 * PI * (1.0 - cosMax);
    return albedo / PI * lamp.emission * ndl * solidAngle;
}

vec3 radiance(Ray ray, inout uint seed) {
    vec3 color = vec3(0.0);
    vec3 throughput = vec3(1.0);
    bool countEmission = true;
    for (int bounce = 0; bounce < BOUNCES; bounce++) {
        float t;
        int index;
        if (!trace(ray, t, index)) {
            break;
        }
        Sphere s = SPHERES[index];
        if (index == LAMP) {
            // Light seen directly or through a specular path; diffuse hits already sampled it.
            if (countEmission) {
                color += throughput * s.emission;
            }
            break;
        }
        vec3 p = ray.origin + ray.dir * t;
        vec3 n = normalize(p - s.center);
        if (dot(n, ray.dir) > 0.0) {
            n = -n;
        }
        color += throughput * sampleLamp(p + n * 1e-3, n, s.albedo, seed);
        countEmission = false;

        throughput *= s.albedo;
        if (bounce >= 2) {
            float survive = clamp(max(throughput.r, max(throughput.g, throughput.b)), 0.05, 0.95);
            if (random(seed) > survive) {
                break;
            }
            throughput /= survive;
        }
        ray = Ray(p + n * 1e-3, cosineHemisphere(n, seed));
    }
    return color;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    uvec2 pixel = uvec2(fragCoord);
    uint seed = hashUint(pixel.x + hashUint(pixel.y + hashUint(uint(iFrame))));

    vec3 total = vec3(0.0);
    for (int s = 0; s < SAMPLES; s++) {
        vec2 jitter = vec2(random(seed), random(seed)) - 0.5;
        vec2 uv = (2.0 * (fragCoord + jitter) - iResolution.xy) / iResolution.y;
        Ray ray = Ray(vec3(0.0, 0.0, 3.4), normalize(vec3(uv, -2.0)));
        total += radiance(ray, seed);
    }
    vec3 color = total / float(SAMPLES);
    color = color / (1.0 + color);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
