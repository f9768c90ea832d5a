// Nested loops, labels of every jump, and empty statements.
float iterate(float x)
{
    int steps = 0;
    while (x > 1.0) {
        x = (mod(x, 2.0) < 1.0) ? x * 0.5 : x * 3.0 + 1.0;
        steps++;
        if (steps > 100) break;
    }
    ;
    for (;;) {
        if (x > 0.5) break;
        x += 0.1;
    }
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            if (j > i) continue;
            x += 0.01;
        }
    }
    return float(steps) * 0.01 + x;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float v = iterate(floor(fragCoord.x));
    if (v < 0.0) discard;
    fragColor = vec4(vec3(fract(v)), 1.0);
}
