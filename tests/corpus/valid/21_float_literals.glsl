// Every literal spelling GLSL ES 3.00 allows.
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float a = 1.;
    float b = .5;
    float c = 1e-3;
    float d = 1.0e+5;
    float e = 2.5E2;
    float f = 3.0f;
    float g = 0.25F;
    float h = 7e1f;
    int i = 42;
    int j = 0x2A;
    int k = 052;
    uint l = 42u;
    uint m = 0xFFU;
    bool yes = true, no = false;
    float sum = a + b + c + d * 1e-6 + e * 0.001 + f + g + h * 0.01;
    sum += float(i + j + k) * 0.001 + float(l + m) * 0.0001;
    fragColor = vec4(fract(sum), yes ? 1.0 : 0.0, no ? 1.0 : 0.0, 1.0);
}
