// Post effects on iChannel0: a separable-looking Gaussian blur done in one pass, bloom from
// a bright-pass, chromatic aberration towards the edges, film grain and a sharpen, all
// sampled with texture, textureLod and texelFetch.

const int BLUR_RADIUS = 4;
const float BLOOM_THRESHOLD = 0.7;

float gaussian(float x, float sigma) {
    return exp(-(x * x) / (2.0 * sigma * sigma));
}

vec3 srgbToLinear(vec3 c) {
    return pow(max(c, vec3(0.0)), vec3(2.2));
}

vec3 linearToSrgb(vec3 c) {
    return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2));
}

vec3 fetchLinear(vec2 uv) {
    return srgbToLinear(texture(iChannel0, uv).rgb);
}

vec3 blur(vec2 uv, vec2 texel, float sigma) {
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int y = -BLUR_RADIUS; y <= BLUR_RADIUS; y++) {
        for (int x = -BLUR_RADIUS; x <= BLUR_RADIUS; x++) {
            vec2 offset = vec2(float(x), float(y));
            float w = gaussian(offset.x, sigma) * gaussian(offset.y, sigma);
            sum += fetchLinear(uv + offset * texel) * w;
            weightSum += w;
        }
    }
    return sum / weightSum;
}

vec3 brightPass(vec3 c) {
    float brightness = max(c.r, max(c.g, c.b));
    float contribution = max(brightness - BLOOM_THRESHOLD, 0.0) / max(brightness, 1e-4);
    return c * contribution;
}

// Bloom from a few coarse mip levels (cheap wide blur).
vec3 bloom(vec2 uv) {
    vec3 sum = vec3(0.0);
    float weight = 1.0;
    float total = 0.0;
    for (int level = 2; level <= 5; level++) {
        vec3 c = srgbToLinear(textureLod(iChannel0, uv, float(level)).rgb);
        sum += brightPass(c) * weight;
        total += weight;
        weight *= 0.7;
    }
    return sum / total;
}

vec3 chromaticAberration(vec2 uv, float amount) {
    vec2 dir = uv - 0.5;
    float r = srgbToLinear(texture(iChannel0, uv + dir * amount).rgb).r;
    float g = srgbToLinear(texture(iChannel0, uv).rgb).g;
    float b = srgbToLinear(texture(iChannel0, uv - dir * amount).rgb).b;
    return vec3(r, g, b);
}

// Unsharp mask from the four direct neighbours, read exactly with texelFetch.
vec3 sharpen(vec2 fragCoord, float strength) {
    ivec2 size = textureSize(iChannel0, 0);
    ivec2 p = clamp(ivec2(fragCoord * vec2(size) / iResolution.xy), ivec2(1), size - 2);
    vec3 center = srgbToLinear(texelFetch(iChannel0, p, 0).rgb);
    vec3 neighbours = srgbToLinear(texelFetch(iChannel0, p + ivec2(1, 0), 0).rgb);
    neighbours += srgbToLinear(texelFetch(iChannel0, p - ivec2(1, 0), 0).rgb);
    neighbours += srgbToLinear(texelFetch(iChannel0, p + ivec2(0, 1), 0).rgb);
    neighbours += srgbToLinear(texelFetch(iChannel0, p - ivec2(0, 1), 0).rgb);
    return max(center + strength * (center - 0.25 * neighbours), vec3(0.0));
}

float grain(vec2 fragCoord, float time) {
    vec2 p = fragCoord + fract(time) * 137.0;
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453) - 0.5;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec2 texel = 1.0 / max(iChannelResolution[0].xy, vec2(1.0));

    // The screen is split in three: blurred, sharpened, and with aberration.
    float split = fract(iTime * 0.05);
    vec3 color;
    if (uv.x < split - 0.33) {
        color = blur(uv, texel, 2.0);
    } else if (uv.x < split) {
        color = sharpen(fragCoord, 0.8);
    } else {
        color = chromaticAberration(uv, 0.015);
    }

    color += 0.6 * bloom(uv);

    float n = grain(fragCoord, iTime);
    color += n * 0.03 * (1.0 - color);

    // Dividers between the three regions.
    float px = 1.0 / iResolution.x;
    float divider = step(abs(uv.x - split), px) + step(abs(uv.x - (split - 0.33)), px);
    color = mix(color, vec3(1.0), clamp(divider, 0.0, 1.0));

    fragColor = vec4(linearToSrgb(color), 1.0);
}
