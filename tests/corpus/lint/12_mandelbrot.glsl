// The Mandelbrot set with a smooth iteration count, an orbit trap and 2x2 supersampling,
// zooming slowly into a point on the boundary. Integer loop counters and explicit
// conversions throughout, as GLSL ES wants them.

const int MAX_ITER = 300;
const float ESCAPE_RADIUS = 256.0;
const vec2 ZOOM_TARGET = vec2(-0.745428, 0.113009);

vec2 complexSquare(vec2 z) {
    return vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y);
}

struct Orbit {
    float smoothIter;  // negative inside the set
    float trap;        // closest approach to the trap cross
};

Orbit mandelbrot(vec2 c) {
    // Skip the main cardioid and the period-2 bulb: they are inside for sure.
    float q = (c.x - 0.25) * (c.x - 0.25) + c.y * c.y;
    if (q * (q + (c.x - 0.25)) < 0.25 * c.y * c.y) {
        return Orbit(-1.0, 0.0);
    }
    if ((c.x + 1.0) * (c.x + 1.0) + c.y * c.y < 0.0625) {
        return Orbit(-1.0, 0.0);
    }

    vec2 z = vec2(0.0);
    float trap = 1e10;
    for (int i = 0; i < MAX_ITER; i++) {
        z = complexSquare(z) + c;
        trap = min(trap, min(abs(z.x), abs(z.y)));
        float r2 = dot(z, z);
        if (r2 > ESCAPE_RADIUS * ESCAPE_RADIUS) {
            // Continuous count: subtract how far past the radius the orbit escaped.
            float nu = log2(log2(r2) * 0.5);
            return Orbit(float(i) + 1.0 - nu, trap);
        }
    }
    return Orbit(-1.0, trap);
}

vec3 palette(float t) {
    vec3 a = vec3(0.5, 0.5, 0.5);
    vec3 b = vec3(0.5, 0.5, 0.5);
    vec3 c = vec3(1.0, 1.0, 1.0);
    vec3 d = vec3(0.0, 0.1, 0.2);
    return a + b * cos(6.28318531 * (c * t + d));
}

vec3 colorFor(Orbit o) {
    if (o.smoothIter < 0.0) {
        return vec3(0.02, 0.01, 0.03) + 0.2 * vec3(exp(-8.0 * o.trap));
    }
    float t = sqrt(o.smoothIter / float(MAX_ITER));
    vec3 color = palette(t * 3.0 + 0.1);
    color *= 0.7 + 0.3 * exp(-20.0 * o.trap);
    return color;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float zoom = pow(0.5, 10.0 * (0.5 - 0.5 * cos(iTime * 0.1)));
    vec3 sum = vec3(0.0);
    const int AA = 2;
    for (int sy = 0; sy < AA; sy++) {
        for (int sx = 0; sx < AA; sx++) {
            vec2 offset = (vec2(float(sx), float(sy)) + 0.5) / float(AA) - 0.5;
            vec2 uv = (2.0 * (fragCoord + offset) - iResolution.xy) / iResolution.y;
            vec2 c = ZOOM_TARGET + uv * 1.5 * zoom;
            sum += colorFor(mandelbrot(c));
        }
    }
    vec3 color = sum / float(AA * AA);
    fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(0.9)), 1.0);
}

// Julia set for the same palette; c follows the mouse when a button is held.
Orbit julia(vec2 z, vec2 c) {
    float trap = 1e10;
    for (int i = 0; i < MAX_ITER; i++) {
        z = complexSquare(z) + c;
        trap = min(trap, length(z - vec2(0.5, 0.0)));
        float r2 = dot(z, z);
        if (r2 > ESCAPE_RADIUS * ESCAPE_RADIUS) {
            float nu = log2(log2(r2) * 0.5);
            return Orbit(float(i) + 1.0 - nu, trap);
        }
    }
    return Orbit(-1.0, trap);
}

vec3 juliaPreview(vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec2 c = iMouse.z > 0.0 ? (2.0 * iMouse.xy - iResolution.xy) / iResolution.y
                            : vec2(-0.8, 0.156);
    return colorFor(julia(uv * 1.3, c));
}

// Distance estimate to the set, for drawing its boundary as a thin line.
float mandelbrotDistance(vec2 c) {
    vec2 z = vec2(0.0);
    vec2 dz = vec2(0.0);
    for (int i = 0; i < MAX_ITER; i++) {
        dz = 2.0 * vec2(z.x * dz.x - z.y * dz.y, z.x * dz.y + z.y * dz.x) + vec2(1.0, 0.0);
        z = complexSquare(z) + c;
        if (dot(z, z) > ESCAPE_RADIUS * ESCAPE_RADIUS) {
            break;
        }
    }
    float r = length(z);
    float dr = max(length(dz), 1e-8);
    return 0.5 * r * log(max(r, 1.0)) / dr;
}
