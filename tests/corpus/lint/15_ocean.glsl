// An ocean: sum-of-waves heightfield (Gerstner-like sharpened sines), ray-heightfield
// intersection by bisection, Fresnel on the view angle for the sky reflection, a subsurface
// tint in the wave crests and a sun glint from a GGX lobe.

const float PI = 3.14159265;
const int WAVES = 6;
const int MARCH_STEPS = 64;
const int REFINE_STEPS = 8;

struct Wave {
    vec2 direction;
    float frequency;
    float amplitude;
    float speed;
    float sharpness;
};

Wave waveAt(int i) {
    float fi = float(i);
    float angle = fi * 1.7 + 0.3;
    float freq = 0.35 * pow(1.6, fi);
    float amp = 0.5 / pow(1.9, fi);
    return Wave(vec2(cos(angle), sin(angle)), freq, amp, sqrt(9.81 * freq) * 0.4, 2.5);
}

float oceanHeight(vec2 p, float time) {
    float h = 0.0;
    for (int i = 0; i < WAVES; i++) {
        Wave w = waveAt(i);
        float phase = dot(w.direction, p) * w.frequency + time * w.speed;
        // Sharpened crests: raise a [0, 1] sine to a power.
        float s = 0.5 + 0.5 * sin(phase);
        h += w.amplitude * (pow(s, w.sharpness) * 2.0 - 1.0);
    }
    return h;
}

vec3 oceanNormal(vec2 p, float time, float dist) {
    float e = 0.01 + 0.002 * dist;
    float h = oceanHeight(p, time);
    float hx = oceanHeight(p + vec2(e, 0.0), time) - h;
    float hz = oceanHeight(p + vec2(0.0, e), time) - h;
    return normalize(vec3(-hx, e, -hz));
}

// March until the ray is below the surface, then bisect between the last two points.
float intersectOcean(vec3 ro, vec3 rd, float time) {
    float tNear = 0.0;
    float tFar = 200.0;
    float hNear = ro.y - oceanHeight(ro.xz, time);
    float t = 0.0;
    float stepSize = 0.5;
    for (int i = 0; i < MARCH_STEPS; i++) {
        t += stepSize;
        vec3 p = ro + rd * t;
        float h = p.y - oceanHeight(p.xz, time);
        if (h < 0.0) {
            tFar = t;
            break;
        }
        tNear = t;
        hNear = h;
        stepSize *= 1.08;
    }
    if (tFar >= 200.0) {
        return -1.0;
    }
    for (int i = 0; i < REFINE_STEPS; i++) {
        float mid = 0.5 * (tNear + tFar);
        vec3 p = ro + rd * mid;
        float h = p.y - oceanHeight(p.xz, time);
        if (h < 0.0) {
            tFar = mid;
        } else {
            tNear = mid;
            hNear = h;
        }
    }
    return 0.5 * (tNear + tFar) + 0.0 * hNear;
}

vec3 sky(vec3 rd, vec3 sunDir) {
    float y = max(rd.y, 0.0);
    vec3 color = mix(vec3(0.7, 0.8, 0.9), vec3(0.2, 0.4, 0.75), pow(y, 0.5));
    float sun = max(dot(rd, sunDir), 0.0);
    color += vec3(1.0, 0.8, 0.6) * (pow(sun, 1000.0) * 20.0 + pow(sun, 16.0) * 0.2);
    return color;
}

float fresnelSchlick(float cosTheta, float f0) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

float ggx(float NoH, float alpha) {
    float a2 = alpha * alpha;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

vec3 shadeOcean(vec3 p, vec3 n, vec3 rd, vec3 sunDir, float dist) {
    vec3 v = -rd;
    float NoV = clamp(dot(n, v), 0.0, 1.0);
    // Water's F0 is about 0.02; the reflection is weighted by the view angle.
    float fresnel = fresnelSchlick(NoV, 0.02);
    vec3 r = reflect(rd, n);
    r.y = abs(r.y);
    vec3 reflected = sky(r, sunDir);

    vec3 deep = vec3(0.0, 0.05, 0.1);
    vec3 shallow = vec3(0.0, 0.3, 0.3);
    float crest = clamp(p.y * 0.8 + 0.3, 0.0, 1.0);
    float sunWrap = clamp(dot(n, sunDir) * 0.5 + 0.5, 0.0, 1.0);
    vec3 refracted = mix(deep, shallow, crest * sunWrap);

    vec3 h = normalize(sunDir + v);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float NoL = clamp(dot(n, sunDir), 0.0, 1.0);
    float VoH = clamp(dot(v, h), 0.0, 1.0);
    float glint = ggx(NoH, 0.08) * fresnelSchlick(VoH, 0.02) * NoL / max(4.0 * NoV, 0.05);

    vec3 color = mix(refracted, reflected, fresnel) + vec3(1.0, 0.9, 0.75) * glint * 3.0;
    float fog = 1.0 - exp(-0.012 * dist);
    return mix(color, sky(vec3(rd.x, 0.0, rd.z), sunDir), fog);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float time = iTime;
    vec3 ro = vec3(0.0, 3.0, time * 2.0);
    vec3 rd = normalize(vec3(uv.x, uv.y - 0.25, 1.5));
    vec3 sunDir = normalize(vec3(0.0, 0.25, 1.0));

    vec3 color;
    float t = rd.y < 0.05 ? intersectOcean(ro, rd, time) : -1.0;
    if (t > 0.0) {
        vec3 p = ro + rd * t;
        vec3 n = oceanNormal(p.xz, time, t);
        color = shadeOcean(p, n, rd, sunDir, t);
    } else {
        color = sky(rd, sunDir);
    }

    color = color / (1.0 + color);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
