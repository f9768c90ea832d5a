float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float sdTorus(vec3 p, vec2 t)
{
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

float scene(vec3 p)
{
    float d = p.y;
    d = min(d, sdBox(p - vec3(-1.0, 0.5, 0.0), vec3(0.5)));
    d = min(d, sdTorus(p - vec3(1.0, 0.5, 0.0), vec2(0.5, 0.2)));
    return d;
}

float softShadow(vec3 ro, vec3 rd, float mint, float maxt, float k)
{
    float res = 1.0;
    float t = mint;
    for (int i = 0; i < 64 && t < maxt; i++) {
        float h = scene(ro + rd * t);
        if (h < 0.001) return 0.0;
        res = min(res, k * h / t);
        t += clamp(h, 0.02, 0.2);
    }
    return clamp(res, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 2.0, -4.0);
    vec3 rd = normalize(vec3(p, 1.5) - vec3(0.0, 0.4, 0.0));
    float t = 0.0;
    for (int i = 0; i < 100; i++) {
        float h = scene(ro + rd * t);
        if (abs(h) < 1e-4 || t > 20.0) break;
        t += h;
    }
    vec3 pos = ro + rd * t;
    float sh = softShadow(pos, normalize(vec3(0.5, 0.8, -0.3)), 0.02, 10.0, 8.0);
    fragColor = vec4(vec3(sh) * exp(-0.05 * t), 1.0);
}
