// 2D signed-distance art: a little landscape of discs, boxes, a star and a heart, combined
// with smooth unions and drawn with pixel-wide anti-aliasing from the distance itself.

const float PI = 3.14159265;
const float TAU = 6.28318531;

float sdCircle(vec2 p, float r) {
    return length(p) - r;
}

float sdBox(vec2 p, vec2 b) {
    vec2 d = abs(p) - b;
    return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0);
}

float sdRoundedBox(vec2 p, vec2 b, float r) {
    return sdBox(p, b - vec2(r)) - r;
}

float sdSegment(vec2 p, vec2 a, vec2 b) {
    vec2 pa = p - a;
    vec2 ba = b - a;
    float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-8), 0.0, 1.0);
    return length(pa - ba * h);
}

// A five-pointed star by folding the plane into one wedge.
float sdStar(vec2 p, float r, float inner) {
    float sector = TAU / 5.0;
    float a = atan(p.x, p.y);
    float folded = mod(a + 0.5 * sector, sector) - 0.5 * sector;
    vec2 q = length(p) * vec2(cos(folded), abs(sin(folded)));
    vec2 tip = vec2(r, 0.0);
    vec2 valley = inner * vec2(cos(0.5 * sector), sin(0.5 * sector));
    vec2 e = valley - tip;
    vec2 w = q - tip;
    float h = clamp(dot(w, e) / dot(e, e), 0.0, 1.0);
    float d = length(w - e * h);
    float side = e.x * w.y - e.y * w.x;
    return side > 0.0 ? -d : d;
}

float sdHeart(vec2 p) {
    p.x = abs(p.x);
    if (p.y + p.x > 1.0) {
        return sqrt(dot(p - vec2(0.25, 0.75), p - vec2(0.25, 0.75))) - sqrt(2.0) / 4.0;
    }
    vec2 a = p - vec2(0.0, 1.0);
    vec2 b = p - 0.5 * max(p.x + p.y, 0.0);
    return sqrt(min(dot(a, a), dot(b, b))) * sign(p.x - p.y);
}

float smoothUnion(float a, float b, float k) {
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

float smoothSubtract(float a, float b, float k) {
    float h = clamp(0.5 - 0.5 * (b + a) / k, 0.0, 1.0);
    return mix(b, -a, h) + k * h * (1.0 - h);
}

mat2 rotate(float a) {
    float c = cos(a);
    float s = sin(a);
    return mat2(c, -s, s, c);
}

// Coverage of a shape of distance d, one pixel (px) wide at its edge.
float fill(float d, float px) {
    return clamp(0.5 - d / px, 0.0, 1.0);
}

float outline(float d, float width, float px) {
    return clamp(0.5 - (abs(d) - width) / px, 0.0, 1.0);
}

vec3 background(vec2 uv) {
    vec3 top = vec3(0.98, 0.86, 0.7);
    vec3 bottom = vec3(0.55, 0.75, 0.9);
    return mix(bottom, top, smoothstep(-1.0, 1.0, uv.y));
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float px = 2.0 / iResolution.y;
    vec3 color = background(uv);

    // Hills: two discs melted together, with a bite taken out.
    float hills = smoothUnion(sdCircle(uv - vec2(-0.9, -1.6), 1.2),
                              sdCircle(uv - vec2(0.7, -1.8), 1.3), 0.3);
    hills = smoothSubtract(sdCircle(uv - vec2(0.1, -0.45), 0.12), hills, 0.05);
    color = mix(color, vec3(0.35, 0.6, 0.3), fill(hills, px));
    color = mix(color, vec3(0.2, 0.35, 0.2), outline(hills, 0.004, px));

    // The sun, breathing slowly, with rays as rotated segments.
    vec2 sunCenter = vec2(0.95, 0.55);
    float sunRadius = 0.16 + 0.01 * sin(iTime * 2.0);
    float sun = sdCircle(uv - sunCenter, sunRadius);
    float rays = 1e3;
    for (int i = 0; i < 12; i++) {
        float a = float(i) * TAU / 12.0 + 0.2 * iTime;
        vec2 dir = vec2(cos(a), sin(a));
        rays = min(rays, sdSegment(uv - sunCenter, dir * 0.22, dir * 0.3) - 0.008);
    }
    color = mix(color, vec3(1.0, 0.75, 0.2), fill(min(sun, rays), px));

    // A house: a rounded box, a roof from a rotated box, a door cut out.
    vec2 housePos = uv - vec2(-0.55, -0.25);
    float walls = sdRoundedBox(housePos, vec2(0.22, 0.16), 0.02);
    vec2 roofPos = rotate(PI / 4.0) * (housePos - vec2(0.0, 0.16));
    float roof = max(sdBox(roofPos, vec2(0.2)), -(housePos.y - 0.16));
    float door = sdRoundedBox(housePos - vec2(0.06, -0.07), vec2(0.045, 0.09), 0.02);
    color = mix(color, vec3(0.9, 0.88, 0.8), fill(max(walls, -door), px));
    color = mix(color, vec3(0.7, 0.25, 0.2), fill(roof, px));
    color = mix(color, vec3(0.25, 0.15, 0.1), outline(walls, 0.003, px));

    // A spinning star and a pulsing heart.
    vec2 starPos = rotate(0.5 * iTime) * (uv - vec2(0.2, 0.5));
    float star = sdStar(starPos, 0.14, 0.06);
    color = mix(color, vec3(1.0, 0.9, 0.3), fill(star, px));

    float beat = 1.0 + 0.08 * pow(0.5 + 0.5 * sin(iTime * 6.0), 4.0);
    vec2 heartPos = (uv - vec2(0.6, -0.15)) / (0.18 * beat) + vec2(0.0, 0.5);
    float heart = sdHeart(heartPos) * 0.18 * beat;
    color = mix(color, vec3(0.9, 0.2, 0.35), fill(heart, px));

    // Distance bands in the sky show the field around the shapes.
    float field = min(min(sun, star), heart);
    float bands = 0.5 + 0.5 * cos(field * 120.0);
    float skyMask = step(0.0, hills) * step(0.0, walls) * step(0.0, field);
    color *= 1.0 - 0.05 * bands * skyMask * exp(-6.0 * field);

    float vignette = 1.0 - 0.25 * dot(uv * 0.5, uv * 0.5);
    color *= vignette;
    fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
