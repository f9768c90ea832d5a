// The ShaderToy shader that the porting guide (porting.md) turns into blob.toml and
// blob.glsl. Paste it into ShaderToy's Image tab, or: glint render site/docs/porting/shadertoy.glsl

float smin(float a, float b, float k) {
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

float map(vec3 p) {
    float ball = length(p - vec3(0.0, 0.5, 0.0)) - 0.5;
    float blob = length(p - vec3(0.5, 0.9, 0.2)) - 0.25;
    return min(smin(ball, blob, 0.25), p.y);
}

vec3 calcNormal(vec3 p) {
    vec2 e = vec2(1e-3, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy),
                          map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx)));
}

float march(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < 200; i++) {
        float h = map(ro + t * rd);
        if (h < 1e-4 * t) return t;
        t += h;
        if (t > 30.0) break;
    }
    return -1.0;
}

float softshadow(vec3 ro, vec3 rd) {
    float res = 1.0, t = 0.02;
    for (int i = 0; i < 64; i++) {
        float h = map(ro + t * rd);
        res = min(res, 8.0 * h / t);
        t += clamp(h, 0.02, 0.2);
        if (res < 0.001 || t > 5.0) break;
    }
    return clamp(res, 0.0, 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 1.2, 3.0);
    vec3 ta = vec3(0.0, 0.4, 0.0);
    vec3 ww = normalize(ta - ro);
    vec3 uu = normalize(cross(vec3(0.0, 1.0, 0.0), ww));
    vec3 vv = cross(ww, uu);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + 1.8 * ww);

    vec3 col = vec3(0.7, 0.8, 1.0);
    float t = march(ro, rd);
    if (t > 0.0) {
        vec3 p = ro + t * rd;
        vec3 n = calcNormal(p);
        vec3 alb = p.y < 0.01 ? vec3(0.4) : vec3(0.6, 0.25, 0.1);
        vec3 sun = normalize(vec3(0.6, 0.8, 0.4));
        float sha = softshadow(p + 1e-3 * n, sun);
        col  = alb * vec3(1.0, 0.9, 0.8) * 1.5 * max(dot(n, sun), 0.0) * sha;
        col += alb * vec3(0.2, 0.3, 0.5) * (0.5 + 0.5 * n.y);
    }
    fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
}
