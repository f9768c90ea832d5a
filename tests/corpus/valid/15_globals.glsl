// Globals, consts and forward declarations (prototypes).
const vec3 kSky = vec3(0.5, 0.7, 1.0);
const int kOctaves = 5;
float gTime;
vec2 gRes, gMouse;

float fbm(vec2 p);
float noise(vec2 p);

float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453123); }

float noise(vec2 p)
{
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i + vec2(0, 0)), hash(i + vec2(1, 0)), u.x),
               mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x), u.y);
}

float fbm(vec2 p)
{
    float v = 0.0, a = 0.5;
    for (int i = 0; i < kOctaves; i++, p *= 2.0, a *= 0.5)
        v += a * noise(p);
    return v;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    gTime = iTime;
    gRes = iResolution.xy;
    gMouse = iMouse.xy / gRes;
    float v = fbm(fragCoord / gRes * 4.0 + gTime * 0.1);
    fragColor = vec4(kSky * v, 1.0);
}
