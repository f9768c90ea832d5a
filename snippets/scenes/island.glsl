// The island of island.toml: value-noise hills under a round falloff, a field glint lights.
//
// p.y - h(x, z) is not a distance: on a slope it overestimates the distance to the ground by
// up to sqrt(1 + |grad h|^2). Here |grad h| stays under about 2.2 (the octaves' amplitudes
// times their frequencies times 1.5, value noise's steepest slope), so the scene declares
// lipschitz = 2.5 and every march divides its steps by it.

float islandHash(vec2 p) {
    return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453);
}

// Value noise in [0, 1]: smooth interpolation of hashed lattice values.
float islandNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    float a = islandHash(i);
    float b = islandHash(i + vec2(1.0, 0.0));
    float c = islandHash(i + vec2(0.0, 1.0));
    float d = islandHash(i + vec2(1.0, 1.0));
    return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

float islandHeight(vec2 xz) {
    float falloff = exp(-dot(xz, xz) / 3.5);
    float hills = 0.5 * islandNoise(xz * 0.9) + 0.25 * islandNoise(xz * 1.9 + 7.0)
        + 0.125 * islandNoise(xz * 4.1 - 3.0);
    return 0.8 * falloff * (0.5 + hills) - 0.45;
}

float sceneDistance(vec3 p) {
    return p.y - islandHeight(p.xz);
}

// 1: sand by the water, 2: grass, 3: bare rock on the heights.
int sceneMaterial(vec3 p) {
    if (p.y < -0.2) return 1;
    return p.y > 0.32 ? 3 : 2;
}

// Each material's albedo, mottled by a finer octave of the same noise.
vec3 sceneAlbedo(vec3 p, int id, vec3 albedo) {
    float mottle = islandNoise(p.xz * 9.0);
    return albedo * (0.75 + 0.5 * mottle);
}
