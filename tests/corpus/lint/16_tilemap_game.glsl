// A 2D tile scene in the style of an old console game: a level stored as bit-packed rows of
// an integer array, tiles drawn by a switch on their type, a parallax background, an animated
// character, and a HUD with digits drawn from 3x5 bitmaps. Integer and bit operations, switch,
// do-while, inout parameters and global state.

#define TILE_EMPTY 0
#define TILE_GROUND 1
#define TILE_BRICK 2
#define TILE_COIN 3

const int LEVEL_WIDTH = 16;
const int LEVEL_HEIGHT = 8;
const float TILE_PIXELS = 24.0;

// Two bits per tile, 16 tiles per row: bottom row first.
const uint LEVEL[LEVEL_HEIGHT] = uint[LEVEL_HEIGHT](
    0x55555555u,
    0x55500555u,
    0x00000000u,
    0x000C0000u,
    0x002A8000u,
    0x00000000u,
    0x0C00000Cu,
    0x00000000u
);

// 3x5 digit glyphs, 15 bits each, top row in the high bits.
const int DIGITS[10] = int[10](
    31599, 9362, 29671, 29391, 23497, 31183, 31215, 29257, 31727, 31695
);

int score = 0;  // written while drawing the coins, read by the HUD

int tileAt(ivec2 cell) {
    if (cell.x < 0 || cell.y < 0 || cell.x >= LEVEL_WIDTH || cell.y >= LEVEL_HEIGHT) {
        return TILE_EMPTY;
    }
    uint row = LEVEL[cell.y];
    uint shift = uint(2 * (LEVEL_WIDTH - 1 - cell.x));
    return int((row >> shift) & 3u);
}

float hash(vec2 p) {
    return fract(sin(dot(p, vec2(41.3, 289.1))) * 12345.678);
}

vec3 drawGround(vec2 local, ivec2 cell) {
    vec3 dirt = vec3(0.55, 0.35, 0.2);
    vec3 grass = vec3(0.3, 0.7, 0.25);
    bool top = tileAt(cell + ivec2(0, 1)) != TILE_GROUND;
    float speckle = hash(floor(local * 8.0) + vec2(cell)) * 0.15;
    vec3 color = dirt * (0.9 + speckle);
    if (top && local.y > 0.75) {
        color = grass * (0.9 + speckle);
    }
    return color;
}

vec3 drawBrick(vec2 local) {
    vec2 brick = local * vec2(2.0, 4.0);
    float row = floor(brick.y);
    brick.x += mod(row, 2.0) * 0.5;
    vec2 f = fract(brick);
    float mortar = step(f.x, 0.06) + step(f.y, 0.1);
    return mix(vec3(0.7, 0.3, 0.2), vec3(0.85, 0.8, 0.7), clamp(mortar, 0.0, 1.0));
}

vec3 drawCoin(vec2 local, float time, inout float alpha) {
    float spin = abs(cos(time * 3.0));
    vec2 p = (local - 0.5) / vec2(max(spin, 0.15), 1.0);
    float d = length(p) - 0.3;
    alpha = clamp(0.5 - d * TILE_PIXELS, 0.0, 1.0);
    float shine = 1.0 - smoothstep(0.0, 0.2, length(p - vec2(-0.1, 0.1)));
    return mix(vec3(0.95, 0.75, 0.1), vec3(1.0, 1.0, 0.7), shine);
}

vec3 background(vec2 world, float time) {
    vec3 sky = mix(vec3(0.55, 0.75, 1.0), vec3(0.35, 0.55, 0.95), world.y / float(LEVEL_HEIGHT));
    // Two layers of hills scrolling at different speeds.
    float far = 2.5 + 0.8 * sin(world.x * 0.4 + time * 0.1);
    float near = 1.5 + 0.6 * sin(world.x * 0.9 + 1.3 + time * 0.25);
    if (world.y < far) {
        sky = mix(sky, vec3(0.45, 0.6, 0.75), 0.7);
    }
    if (world.y < near) {
        sky = vec3(0.35, 0.55, 0.4);
    }
    return sky;
}

// The character: a rounded box body and eyes, walking along the ground.
vec4 drawCharacter(vec2 world, float time) {
    float x = mod(time * 2.0, float(LEVEL_WIDTH));
    float bounce = abs(sin(time * 8.0)) * 0.1;
    vec2 p = world - vec2(x, 1.55 + bounce);
    vec2 q = abs(p) - vec2(0.3, 0.45);
    float body = length(max(q, 0.0)) + min(max(q.x, q.y), 0.0) - 0.08;
    float alpha = clamp(0.5 - body * TILE_PIXELS, 0.0, 1.0);
    vec3 color = vec3(0.9, 0.25, 0.2);
    float eye = length(p - vec2(0.12, 0.2)) - 0.07;
    if (eye < 0.0) {
        color = vec3(1.0);
        if (length(p - vec2(0.14, 0.2)) < 0.035) {
            color = vec3(0.0);
        }
    }
    return vec4(color, alpha);
}

// A number in 3x5 digits; `pos` is in HUD pixels, origin at the number's bottom left.
float drawNumber(vec2 pos, int value) {
    int digitCount = 0;
    int v = value;
    do {
        digitCount++;
        v /= 10;
    } while (v > 0 && digitCount < 6);
    ivec2 p = ivec2(floor(pos));
    if (p.y < 0 || p.y > 4 || p.x < 0 || p.x >= digitCount * 4) {
        return 0.0;
    }
    int digitIndex = digitCount - 1 - p.x / 4;
    int column = p.x % 4;
    if (column == 3) {
        return 0.0;
    }
    int d = value;
    for (int i = 0; i < digitIndex; i++) {
        d /= 10;
    }
    int bit = (4 - p.y) * 3 + (2 - column);
    return float((DIGITS[d % 10] >> bit) & 1);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float time = iTime;
    float scroll = max(0.0, mod(time * 2.0, float(LEVEL_WIDTH)) - 6.0);
    vec2 world = fragCoord / TILE_PIXELS + vec2(scroll, 0.0);
    ivec2 cell = ivec2(floor(world));
    vec2 local = fract(world);

    vec3 color = background(world, time);
    int tile = tileAt(cell);
    switch (tile) {
        case TILE_GROUND:
            color = drawGround(local, cell);
            break;
        case TILE_BRICK:
            color = drawBrick(local);
            break;
        case TILE_COIN: {
            float alpha = 0.0;
            vec3 coin = drawCoin(local, time + float(cell.x), alpha);
            color = mix(color, coin, alpha);
            break;
        }
        default:
            break;
    }

    // Count the coins in the level for the HUD (every pixel does the same small loop).
    for (int y = 0; y < LEVEL_HEIGHT; y++) {
        for (int x = 0; x < LEVEL_WIDTH; x++) {
            if (tileAt(ivec2(x, y)) == TILE_COIN) {
                score += 100;
            }
        }
    }

    vec4 hero = drawCharacter(world, time);
    color = mix(color, hero.rgb, hero.a);

    vec2 hud = (fragCoord - vec2(12.0, iResolution.y - 36.0)) / 4.0;
    float digits = drawNumber(hud, score);
    color = mix(color, vec3(1.0), digits);

    fragColor = vec4(color, 1.0);
}
