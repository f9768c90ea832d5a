// Heightfield terrain from fractal value noise, raymarched with a step that grows with
// distance, shaded by slope and height, with sun shadows, atmospheric fog and a sky.

const float PI = 3.14159265;
const int OCTAVES = 6;
const mat2 OCTAVE_ROTATION = mat2(0.8, -0.6, 0.6, 0.8);

float hash(vec2 p) {
    p = fract(p * vec2(123.34, 456.21));
    p += dot(p, p + 45.32);
    return fract(p.x * p.y);
}

// Value noise with a quintic fade, returning the value and its derivatives.
vec3 noised(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec2 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);

    float a = hash(i);
    float b = hash(i + vec2(1.0, 0.0));
    float c = hash(i + vec2(0.0, 1.0));
    float d = hash(i + vec2(1.0, 1.0));

    float k1 = b - a;
    float k2 = c - a;
    float k4 = a - b - c + d;
    float value = a + k1 * u.x + k2 * u.y + k4 * u.x * u.y;
    vec2 gradient = du * vec2(k1 + k4 * u.y, k2 + k4 * u.x);
    return vec3(value, gradient);
}

// Octaves whose contribution shrinks where the accumulated slope is steep (eroded look).
float terrain(vec2 p) {
    float height = 0.0;
    float amplitude = 0.5;
    vec2 slope = vec2(0.0);
    for (int i = 0; i < OCTAVES; i++) {
        vec3 n = noised(p);
        slope += n.yz;
        height += amplitude * n.x / (1.0 + dot(slope, slope));
        amplitude *= 0.5;
        p = OCTAVE_ROTATION * p * 2.0;
    }
    return height;
}

float heightAt(vec2 xz) {
    return 3.0 * terrain(xz * 0.25) - 1.0;
}

vec3 terrainNormal(vec3 p, float t) {
    float e = 0.002 * t;
    float hx = heightAt(p.xz + vec2(e, 0.0)) - heightAt(p.xz - vec2(e, 0.0));
    float hz = heightAt(p.xz + vec2(0.0, e)) - heightAt(p.xz - vec2(0.0, e));
    return normalize(vec3(-hx, 2.0 * e, -hz));
}

float marchTerrain(vec3 ro, vec3 rd, float tmax) {
    float t = 0.1;
    for (int i = 0; i < 200; i++) {
        vec3 p = ro + rd * t;
        float h = p.y - heightAt(p.xz);
        if (abs(h) < 0.001 * t || t > tmax) {
            break;
        }
        t += 0.4 * h;
    }
    return t;
}

float terrainShadow(vec3 ro, vec3 rd) {
    float res = 1.0;
    float t = 0.05;
    for (int i = 0; i < 48; i++) {
        vec3 p = ro + rd * t;
        float h = p.y - heightAt(p.xz);
        res = min(res, 16.0 * h / t);
        t += clamp(h, 0.05, 0.6);
        if (res < 0.0 || t > 20.0) {
            break;
        }
    }
    return clamp(res, 0.0, 1.0);
}

vec3 skyColor(vec3 rd, vec3 sunDir) {
    float sun = clamp(dot(rd, sunDir), 0.0, 1.0);
    vec3 sky = mix(vec3(0.75, 0.8, 0.85), vec3(0.25, 0.45, 0.8), clamp(rd.y * 1.5, 0.0, 1.0));
    sky += vec3(1.0, 0.7, 0.4) * 0.25 * pow(sun, 8.0);
    sky += vec3(1.0, 0.9, 0.7) * pow(sun, 512.0);
    return sky;
}

vec3 terrainColor(vec3 p, vec3 n) {
    vec3 rock = vec3(0.35, 0.3, 0.25);
    vec3 grass = vec3(0.2, 0.35, 0.12);
    vec3 snow = vec3(0.9, 0.92, 0.95);
    float flatness = smoothstep(0.6, 0.9, n.y);
    vec3 base = mix(rock, grass, flatness);
    float snowLine = smoothstep(0.9, 1.3, p.y + 0.3 * n.y);
    return mix(base, snow, snowLine * flatness);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 sunDir = normalize(vec3(-0.6, 0.35, -0.7));

    float travel = iTime * 0.6;
    vec3 ro = vec3(0.0, 0.0, travel);
    ro.y = heightAt(ro.xz) + 1.2;
    vec3 target = vec3(0.0, ro.y - 0.4, travel + 3.0);
    vec3 forward = normalize(target - ro);
    vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, forward);
    vec3 rd = normalize(uv.x * right + uv.y * up + 1.6 * forward);

    const float tmax = 40.0;
    float t = marchTerrain(ro, rd, tmax);
    vec3 color;
    if (t < tmax) {
        vec3 p = ro + rd * t;
        vec3 n = terrainNormal(p, t);
        vec3 albedo = terrainColor(p, n);
        float sunDiffuse = max(dot(n, sunDir), 0.0);
        float shadow = sunDiffuse > 0.0 ? terrainShadow(p + n * 0.01, sunDir) : 0.0;
        float skyDiffuse = clamp(0.5 + 0.5 * n.y, 0.0, 1.0);
        vec3 light = vec3(2.2, 1.9, 1.5) * sunDiffuse * shadow;
        light += vec3(0.25, 0.35, 0.5) * skyDiffuse;
        color = albedo * light / PI * 2.0;
        float fog = 1.0 - exp(-0.06 * t);
        color = mix(color, skyColor(rd, sunDir), fog);
    } else {
        color = skyColor(rd, sunDir);
    }

    color = pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2));
    fragColor = vec4(color, 1.0);
}
