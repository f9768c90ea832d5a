#define MAX_STEPS 128
#define MAX_DIST 100.0
#define SURF_EPS 0.001

float sdSphere(vec3 p, float r) { return length(p) - r; }
float sdPlane(vec3 p) { return p.y + 1.0; }

float map(vec3 p)
{
    return min(sdSphere(p - vec3(0.0, 0.0, 4.0), 1.0), sdPlane(p));
}

vec3 calcNormal(vec3 p)
{
    const vec2 e = vec2(1e-3, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float march(vec3 ro, vec3 rd)
{
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        float d = map(ro + rd * t);
        if (d < SURF_EPS) break;
        t += d;
        if (t > MAX_DIST) return -1.0;
    }
    return t;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0);
    vec3 rd = normalize(vec3(uv, 1.5));
    float t = march(ro, rd);
    vec3 col = vec3(0.6, 0.7, 0.9) - 0.5 * rd.y;
    if (t > 0.0) {
        vec3 n = calcNormal(ro + rd * t);
        vec3 l = normalize(vec3(0.6, 0.8, -0.4));
        col = vec3(0.9, 0.6, 0.3) * max(dot(n, l), 0.0) + 0.05;
    }
    fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
}
