// The island of island.toml: value-noise hills under a round falloff, a field glint lights.
//
// p.y - h(x, z) is not a distance: on a slope it overestimates the distance to the ground by
// up to sqrt(1 + |grad h|^2). Here |grad h| stays under about 2.2 (the octaves' amplitudes
// times their frequencies times 1.5, value noise's steepest slope), so the scene declares
// lipschitz = 2.5 and every march divides its steps by it.

// A lattice point's value in [0, 1]: its integer coordinates mixed by integer multiplies and
// shifts (the lowbias32 finaliser). Not fract(sin(...)): sin of large arguments differs from
// one GPU (or one software rasteriser) to the next, and so would the island.
float islandHash(vec2 p) {
    uvec2 q = uvec2(ivec2(p) + 4096);
    uint h = q.x * 0x9E3779B1u ^ (q.y + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return float(h >> 8) / 16777215.0;
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
