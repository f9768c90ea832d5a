void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    int n = int(fragCoord.x);
    int a = -n;
    int b = ~n;
    int c = ++n;
    int d = --n;
    int e = n++ + n--;
    bool f = !(a > 0);
    vec2 v = -fragCoord.yx;
    v.x++;
    --v.y;
    float g = -(-v.x);
    fragColor = vec4(float(a + b + c + d + e) * 1e-3, f ? 1.0 : 0.0, g * 1e-3, 1.0);
}
