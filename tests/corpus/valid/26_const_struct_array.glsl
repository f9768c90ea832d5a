struct Sphere { vec3 c; float r; vec3 col; };

const int NUM_SPHERES = 3;
const Sphere spheres[NUM_SPHERES] = Sphere[](
    Sphere(vec3(-1.0, 0.0, 4.0), 0.8, vec3(1.0, 0.3, 0.3)),
    Sphere(vec3( 1.0, 0.0, 4.0), 0.8, vec3(0.3, 1.0, 0.3)),
    Sphere(vec3( 0.0, 1.2, 5.0), 0.8, vec3(0.3, 0.3, 1.0))
);

float iSphere(vec3 ro, vec3 rd, Sphere s)
{
    vec3 oc = ro - s.c;
    float b = dot(oc, rd);
    float c = dot(oc, oc) - s.r * s.r;
    float h = b * b - c;
    return h < 0.0 ? -1.0 : -b - sqrt(h);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 rd = normalize(vec3(p, 1.5));
    vec3 col = vec3(0.1);
    float best = 1e9;
    for (int i = 0; i < NUM_SPHERES; i++) {
        float t = iSphere(vec3(0.0), rd, spheres[i]);
        if (t > 0.0 && t < best) {
            best = t;
            col = spheres[i].col * (0.3 + 0.7 * max(0.0, -dot(normalize(rd * t - spheres[i].c), rd)));
        }
    }
    fragColor = vec4(col, 1.0);
}
