// A small raymarched still life: a sphere, a rounded box and a torus on a floor, lit by a
// sun with penumbra shadows and a sky fill attenuated by ambient occlusion.

const int MAX_STEPS = 128;
const float MAX_DIST = 40.0;
const float SURF_EPS = 0.0005;
const float PI = 3.14159265;

struct Hit {
    float dist;
    float material;
};

float sdSphere(vec3 p, float r) {
    return length(p) - r;
}

float sdRoundBox(vec3 p, vec3 b, float r) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdTorus(vec3 p, vec2 t) {
    vec2 q = vec2(length(p.xz) - t.x, p.y);
    return length(q) - t.y;
}

mat2 rot(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat2(c, -s, s, c);
}

Hit closer(Hit a, Hit b) {
    return a.dist < b.dist ? a : b;
}

Hit scene(vec3 p) {
    Hit h = Hit(p.y + 1.0, 0.0);
    h = closer(h, Hit(sdSphere(p - vec3(-1.6, 0.0, 0.0), 1.0), 1.0));
    vec3 q = p - vec3(1.2, -0.3, 0.4);
    q.xz *= rot(0.6);
    h = closer(h, Hit(sdRoundBox(q, vec3(0.55, 0.55, 0.55), 0.12), 2.0));
    vec3 t = p - vec3(0.0, -0.75, -1.8);
    h = closer(h, Hit(sdTorus(t, vec2(0.8, 0.25)), 3.0));
    return h;
}

vec3 calcNormal(vec3 p) {
    // Tetrahedral differences: four evaluations instead of six.
    const vec2 k = vec2(1.0, -1.0);
    const float h = 0.0005;
    return normalize(k.xyy * scene(p + k.xyy * h).dist +
                     k.yyx * scene(p + k.yyx * h).dist +
                     k.yxy * scene(p + k.yxy * h).dist +
                     k.xxx * scene(p + k.xxx * h).dist);
}

Hit march(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; i++) {
        Hit h = scene(ro + rd * t);
        if (h.dist < SURF_EPS * t) {
            return Hit(t, h.material);
        }
        t += h.dist;
        if (t > MAX_DIST) {
            break;
        }
    }
    return Hit(MAX_DIST, -1.0);
}

// Penumbra estimate from the closest miss along the shadow ray (k sets the hardness).
float softShadow(vec3 ro, vec3 rd, float tmin, float tmax, float k) {
    float res = 1.0;
    float t = tmin;
    for (int i = 0; i < 64; i++) {
        float h = scene(ro + rd * t).dist;
        res = min(res, k * h / t);
        t += clamp(h, 0.01, 0.25);
        if (res < 0.001 || t > tmax) {
            break;
        }
    }
    return clamp(res, 0.0, 1.0);
}

float ambientOcclusion(vec3 p, vec3 n) {
    float occ = 0.0;
    float weight = 1.0;
    for (int i = 1; i <= 5; i++) {
        float h = 0.02 + 0.12 * float(i);
        float d = scene(p + n * h).dist;
        occ += (h - d) * weight;
        weight *= 0.85;
    }
    return clamp(1.0 - 2.5 * occ, 0.0, 1.0);
}

vec3 albedo(float material, vec3 p) {
    if (material < 0.5) {
        float checker = mod(floor(p.x) + floor(p.z), 2.0);
        return mix(vec3(0.25), vec3(0.55), checker);
    }
    if (material < 1.5) {
        return vec3(0.75, 0.2, 0.15);
    }
    if (material < 2.5) {
        return vec3(0.2, 0.45, 0.75);
    }
    return vec3(0.85, 0.7, 0.3);
}

vec3 sky(vec3 rd) {
    float t = clamp(0.5 + 0.5 * rd.y, 0.0, 1.0);
    return mix(vec3(0.8, 0.85, 0.9), vec3(0.3, 0.5, 0.85), t);
}

vec3 shade(vec3 ro, vec3 rd) {
    Hit h = march(ro, rd);
    if (h.material < 0.0) {
        return sky(rd);
    }
    vec3 p = ro + rd * h.dist;
    vec3 n = calcNormal(p);
    vec3 sunDir = normalize(vec3(0.6, 0.7, -0.4));
    vec3 base = albedo(h.material, p);

    float ndl = max(dot(n, sunDir), 0.0);
    float shadow = ndl > 0.0 ? softShadow(p + n * 0.002, sunDir, 0.01, 10.0, 12.0) : 0.0;
    float ao = ambientOcclusion(p, n);

    vec3 halfVec = normalize(sunDir - rd);
    float ndh = max(dot(n, halfVec), 0.0);
    float spec = pow(ndh, 48.0) * (48.0 + 8.0) / (8.0 * PI);

    vec3 color = base / PI * ndl * shadow * vec3(3.2, 3.0, 2.7);
    color += spec * 0.04 * ndl * shadow * vec3(3.2, 3.0, 2.7);
    float skyAmount = clamp(0.5 + 0.5 * n.y, 0.0, 1.0);
    color += base * sky(n) * skyAmount * ao * 0.35;

    float fog = 1.0 - exp(-0.0025 * h.dist * h.dist);
    return mix(color, sky(rd), fog);
}

mat3 camera(vec3 ro, vec3 target) {
    vec3 forward = normalize(target - ro);
    vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, forward);
    return mat3(right, up, forward);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float angle = 0.2 * iTime;
    vec3 ro = vec3(5.0 * sin(angle), 1.8, 5.0 * cos(angle));
    mat3 cam = camera(ro, vec3(0.0, -0.3, 0.0));
    vec3 rd = cam * normalize(vec3(uv, 1.8));

    vec3 color = shade(ro, rd);
    color = color / (1.0 + color);
    color = pow(color, vec3(1.0 / 2.2));
    fragColor = vec4(color, 1.0);
}
