// Mandelbrot with a do-while loop and an early continue.
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 c = (fragCoord - vec2(0.7, 0.5) * iResolution.xy) / iResolution.y * 2.5;
    vec2 z = vec2(0.0);
    int n = 0;
    do {
        z = vec2(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y) + c;
        n++;
        if (dot(z, z) > 4.0) break;
    } while (n < 200);
    float k = float(n) / 200.0;
    int i = 0;
    float acc = 0.0;
    while (i < 8) {
        i += 1;
        if (i == 3) continue;
        acc += 0.01;
    }
    fragColor = vec4(vec3(sqrt(k)) + acc, 1.0);
}
