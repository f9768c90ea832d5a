// Integer hash with unsigned bit operations.
uint hash(uint x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

int mixBits(int a, int b)
{
    int r = (a << 3) | (b >> 1);
    r &= 0xFF;
    r |= ~a & 7;
    r <<= 1;
    r >>= 2;
    r %= 97;
    return r ^ (a & b);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    uvec2 p = uvec2(fragCoord);
    uint h = hash(p.x + hash(p.y) + uint(iFrame));
    float v = float(h & 0xFFFFu) / 65535.0;
    float w = float(mixBits(int(p.x), int(p.y))) / 255.0;
    fragColor = vec4(v, w, float(017 + 0x1F) / 100.0, 1.0);
}
