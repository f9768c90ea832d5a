// The classic polar tunnel: screen position to (angle, 1/radius) texture coordinates,
// textured from iChannel0, with depth fog, a light ring that travels down the tunnel and a
// cheap bump from the texture's luminance.

const float PI = 3.14159265;
const float TUNNEL_SPEED = 0.35;
const float TWIST = 0.15;

float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// Wander the tunnel's centre so the camera seems to follow a curving path.
vec2 pathOffset(float z) {
    return vec2(0.25 * sin(z * 0.6), 0.18 * cos(z * 0.45));
}

vec2 tunnelCoords(vec2 p, float time, out float depth) {
    float radius = max(length(p), 1e-3);
    float angle = atan(p.y, p.x);
    depth = 1.0 / radius;
    float u = angle / PI + TWIST * depth;
    float v = depth + time * TUNNEL_SPEED * 4.0;
    return vec2(u, v);
}

vec3 sampleWall(vec2 tc, vec2 dx, vec2 dy) {
    // textureGrad keeps mip selection stable across the angle's seam at +-PI.
    return textureGrad(iChannel0, tc, dx, dy).rgb;
}

vec3 stripes(vec2 tc) {
    float s = 0.5 + 0.5 * sin(tc.y * 12.0);
    float r = 0.5 + 0.5 * sin(tc.x * PI * 8.0);
    return mix(vec3(0.15, 0.1, 0.2), vec3(0.6, 0.4, 0.8), s * r);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float time = iTime;

    vec2 center = pathOffset(time) - pathOffset(time + 1.0);
    vec2 p = uv - center;

    float depth;
    vec2 tc = tunnelCoords(p, time, depth);

    // Derivatives of the continuous part only: the wrap of atan is a jump, not a slope.
    vec2 tcAlt = vec2(fract(tc.x * 0.5 + 0.5), tc.y);
    vec2 dx = dFdx(tc);
    vec2 dy = dFdy(tc);
    vec2 dxAlt = dFdx(tcAlt);
    vec2 dyAlt = dFdy(tcAlt);
    if (dot(dxAlt, dxAlt) < dot(dx, dx)) {
        dx = dxAlt;
    }
    if (dot(dyAlt, dyAlt) < dot(dy, dy)) {
        dy = dyAlt;
    }

    vec3 wall = sampleWall(tc, dx, dy);
    wall = mix(wall, stripes(tc), 0.3);

    // A bump from neighbouring texels' luminance, lit from the camera.
    vec2 texel = 1.0 / max(iChannelResolution[0].xy, vec2(1.0));
    float h0 = luminance(texture(iChannel0, tc).rgb);
    float hu = luminance(texture(iChannel0, tc + vec2(texel.x, 0.0)).rgb);
    float hv = luminance(texture(iChannel0, tc + vec2(0.0, texel.y)).rgb);
    vec3 bumpNormal = normalize(vec3(h0 - hu, h0 - hv, 0.1));
    float facing = clamp(bumpNormal.z, 0.0, 1.0);
    wall *= 0.6 + 0.4 * facing;

    // A ring of light moving towards the viewer.
    float ringPos = fract(time * 0.25) * 8.0;
    float ring = exp(-4.0 * abs(depth - ringPos));
    vec3 glow = vec3(1.0, 0.6, 0.3) * ring * 1.5;

    float fog = exp(-0.12 * depth);
    vec3 color = wall * fog + glow * fog;

    // Brighten the far end, where the tunnel would open up.
    float farEnd = smoothstep(6.0, 30.0, depth);
    color = mix(color, vec3(0.9, 0.85, 0.7), farEnd * 0.6);

    color *= 1.0 - 0.3 * dot(uv * 0.6, uv * 0.6);
    color = clamp(color, 0.0, 1.0);
    fragColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}

// Mip level a shader would use for the tunnel texture: a helper for tuning TWIST, unused in
// the image but kept to document the relation between depth and texel footprint.
float tunnelMipLevel(vec2 dx, vec2 dy, vec2 size) {
    vec2 ddx = dx * size;
    vec2 ddy = dy * size;
    float footprint = max(dot(ddx, ddx), dot(ddy, ddy));
    return 0.5 * log2(max(footprint, 1.0));
}

vec2 tunnelDebugGrid(vec2 tc) {
    vec2 cell = abs(fract(tc * vec2(8.0, 2.0)) - 0.5);
    return smoothstep(0.45, 0.5, cell);
}
