// Animated Voronoi: distance to the nearest and second-nearest feature points, cell borders
// from the exact bisector distance, cell colours from a hash, and a crackle pattern.

const float TAU = 6.28318531;

vec2 hash2(vec2 p) {
    p = vec2(dot(p, vec2(127.1, 311.7)), dot(p, vec2(269.5, 183.3)));
    return fract(sin(p) * 43758.5453);
}

vec3 hash3(vec2 p) {
    vec3 q = vec3(dot(p, vec2(127.1, 311.7)),
                  dot(p, vec2(269.5, 183.3)),
                  dot(p, vec2(419.2, 371.9)));
    return fract(sin(q) * 43758.5453);
}

// Feature point of cell `cell`, orbiting inside it.
vec2 featurePoint(vec2 cell, float time) {
    vec2 h = hash2(cell);
    return 0.5 + 0.4 * sin(time + TAU * h);
}

// x: distance to the nearest point, y: distance to the border, zw: the nearest cell.
vec4 voronoi(vec2 p, float time) {
    vec2 cell = floor(p);
    vec2 local = fract(p);

    vec2 nearestCell = vec2(0.0);
    vec2 nearestVec = vec2(0.0);
    float nearest = 8.0;
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            vec2 offset = vec2(float(i), float(j));
            vec2 r = offset + featurePoint(cell + offset, time) - local;
            float d = dot(r, r);
            if (d < nearest) {
                nearest = d;
                nearestVec = r;
                nearestCell = offset;
            }
        }
    }

    // Border distance: project onto the bisectors with the neighbours of the nearest cell.
    float border = 8.0;
    for (int j = -2; j <= 2; j++) {
        for (int i = -2; i <= 2; i++) {
            vec2 offset = nearestCell + vec2(float(i), float(j));
            vec2 r = offset + featurePoint(cell + offset, time) - local;
            vec2 diff = r - nearestVec;
            if (dot(diff, diff) > 1e-5) {
                border = min(border, dot(0.5 * (nearestVec + r), normalize(diff)));
            }
        }
    }
    return vec4(sqrt(nearest), border, cell + nearestCell);
}

float crackle(vec2 p, float time) {
    float sum = 0.0;
    float amplitude = 0.5;
    for (int octave = 0; octave < 3; octave++) {
        vec4 v = voronoi(p, time);
        sum += amplitude * smoothstep(0.0, 0.08, v.y);
        p *= 2.1;
        amplitude *= 0.5;
    }
    return sum;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float time = iTime * 0.6;
    vec2 p = uv * 4.0 + vec2(0.3 * time, 0.0);

    vec4 v = voronoi(p, time);
    vec3 cellColor = 0.35 + 0.55 * hash3(v.zw);

    // Shade each cell as a shallow dome, darker towards its border.
    float dome = clamp(1.0 - v.x, 0.0, 1.0);
    vec3 color = cellColor * (0.5 + 0.5 * dome);

    float px = 8.0 / iResolution.y;
    float edge = 1.0 - smoothstep(0.0, px, v.y - 0.02);
    color = mix(color, vec3(0.05), edge);

    // The point itself, as a small dot.
    float marker = 1.0 - smoothstep(0.04, 0.04 + px, v.x);
    color = mix(color, vec3(1.0), marker);

    // Mouse-controlled crackle overlay on the left side.
    float split = iMouse.z > 0.0 ? iMouse.x / iResolution.x : 0.5;
    if (fragCoord.x < split * iResolution.x) {
        float c = crackle(p * 0.5, time);
        color *= 0.6 + 0.4 * c;
    }

    fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}

// Manhattan and Chebyshev variants for comparison; they give square and diamond cells.
float voronoiManhattan(vec2 p) {
    vec2 cell = floor(p);
    vec2 local = fract(p);
    float nearest = 8.0;
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            vec2 offset = vec2(float(i), float(j));
            vec2 r = offset + hash2(cell + offset) - local;
            nearest = min(nearest, abs(r.x) + abs(r.y));
        }
    }
    return nearest;
}

float voronoiChebyshev(vec2 p) {
    vec2 cell = floor(p);
    vec2 local = fract(p);
    float nearest = 8.0;
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            vec2 offset = vec2(float(i), float(j));
            vec2 r = offset + hash2(cell + offset) - local;
            nearest = min(nearest, max(abs(r.x), abs(r.y)));
        }
    }
    return nearest;
}
