// A slab of volumetric cloud: 3D value-noise fbm density, ray marched front to back with
// Beer-Lambert transmittance, a Henyey-Greenstein phase function for the sun and a short
// light march for self-shadowing.

const float PI = 3.14159265;
const float CLOUD_BOTTOM = 1.5;
const float CLOUD_TOP = 4.0;
const int VIEW_STEPS = 64;
const int LIGHT_STEPS = 6;
const float EXTINCTION = 1.2;  // per unit length at density 1

float hash13(vec3 p) {
    p = fract(p * 0.1031);
    p += dot(p, p.zyx + 31.32);
    return fract((p.x + p.y) * p.z);
}

float noise3(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fract(p);
    vec3 u = f * f * (3.0 - 2.0 * f);
    float n000 = hash13(i);
    float n100 = hash13(i + vec3(1.0, 0.0, 0.0));
    float n010 = hash13(i + vec3(0.0, 1.0, 0.0));
    float n110 = hash13(i + vec3(1.0, 1.0, 0.0));
    float n001 = hash13(i + vec3(0.0, 0.0, 1.0));
    float n101 = hash13(i + vec3(1.0, 0.0, 1.0));
    float n011 = hash13(i + vec3(0.0, 1.0, 1.0));
    float n111 = hash13(i + vec3(1.0, 1.0, 1.0));
    float x00 = mix(n000, n100, u.x);
    float x10 = mix(n010, n110, u.x);
    float x01 = mix(n001, n101, u.x);
    float x11 = mix(n011, n111, u.x);
    return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

float fbm(vec3 p) {
    float sum = 0.0;
    float amplitude = 0.5;
    for (int i = 0; i < 5; i++) {
        sum += amplitude * noise3(p);
        p = p * 2.03 + vec3(1.7, 9.2, 3.1);
        amplitude *= 0.5;
    }
    return sum;
}

float density(vec3 p, float time) {
    float height = (p.y - CLOUD_BOTTOM) / (CLOUD_TOP - CLOUD_BOTTOM);
    float profile = smoothstep(0.0, 0.2, height) * (1.0 - smoothstep(0.6, 1.0, height));
    vec3 q = p * 0.6 + vec3(time * 0.2, 0.0, time * 0.05);
    float d = fbm(q) - 0.45;
    return max(d * profile * 3.0, 0.0);
}

// Henyey-Greenstein phase, normalised over the sphere; g > 0 scatters forward.
float phaseHG(float cosTheta, float g) {
    float g2 = g * g;
    float denom = 1.0 + g2 - 2.0 * g * cosTheta;
    return (1.0 - g2) / (4.0 * PI * denom * sqrt(denom));
}

float lightTransmittance(vec3 p, vec3 sunDir, float time) {
    float stepSize = (CLOUD_TOP - CLOUD_BOTTOM) / float(LIGHT_STEPS) * 0.5;
    float opticalDepth = 0.0;
    for (int i = 0; i < LIGHT_STEPS; i++) {
        p += sunDir * stepSize;
        opticalDepth += density(p, time) * stepSize;
    }
    return exp(-EXTINCTION * opticalDepth);
}

vec2 slabInterval(vec3 ro, vec3 rd) {
    if (abs(rd.y) < 1e-4) {
        return vec2(-1.0);
    }
    float t0 = (CLOUD_BOTTOM - ro.y) / rd.y;
    float t1 = (CLOUD_TOP - ro.y) / rd.y;
    return vec2(max(min(t0, t1), 0.0), max(t0, t1));
}

vec3 skyColor(vec3 rd, vec3 sunDir) {
    float sun = clamp(dot(rd, sunDir), 0.0, 1.0);
    vec3 sky = mix(vec3(0.6, 0.7, 0.85), vec3(0.15, 0.35, 0.7), clamp(rd.y, 0.0, 1.0));
    return sky + vec3(1.0, 0.85, 0.6) * pow(sun, 256.0) * 4.0;
}

vec4 marchClouds(vec3 ro, vec3 rd, vec3 sunDir, float time, float jitter) {
    vec2 range = slabInterval(ro, rd);
    if (range.y <= range.x) {
        return vec4(0.0, 0.0, 0.0, 1.0);
    }
    float far = min(range.y, 30.0);
    float stepSize = (far - range.x) / float(VIEW_STEPS);
    float t = range.x + stepSize * jitter;
    vec3 sunLight = vec3(6.0, 5.6, 5.0);
    vec3 ambient = vec3(0.35, 0.45, 0.6);
    float cosTheta = dot(rd, sunDir);
    float phase = mix(phaseHG(cosTheta, 0.6), phaseHG(cosTheta, -0.25), 0.3);

    vec3 scattered = vec3(0.0);
    float transmittance = 1.0;
    for (int i = 0; i < VIEW_STEPS; i++) {
        vec3 p = ro + rd * t;
        float d = density(p, time);
        if (d > 0.0) {
            float sigma = EXTINCTION * d;
            float stepTransmittance = exp(-sigma * stepSize);
            vec3 light = sunLight * phase * lightTransmittance(p, sunDir, time) + ambient * d;
            // Energy-conserving integration of the in-scattered light over the step.
            vec3 integrated = light * (1.0 - stepTransmittance);
            scattered += transmittance * integrated;
            transmittance *= stepTransmittance;
            if (transmittance < 0.01) {
                break;
            }
        }
        t += stepSize;
    }
    return vec4(scattered, transmittance);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ro = vec3(0.0, 0.5, 0.0);
    vec3 rd = normalize(vec3(uv.x, uv.y + 0.6, 1.4));
    vec3 sunDir = normalize(vec3(0.3, 0.35, 0.9));

    float jitter = fract(sin(dot(fragCoord, vec2(12.9898, 78.233))) * 43758.5453);
    vec4 clouds = marchClouds(ro, rd, sunDir, iTime, jitter);
    vec3 color = skyColor(rd, sunDir) * clouds.a + clouds.rgb;

    color = 1.0 - exp(-color);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
