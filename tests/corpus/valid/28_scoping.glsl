// Shadowing and block scopes.
float x = 1.0;

float f(float x)
{
    {
        float x = 2.0;
        x += 1.0;
    }
    return x;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float y = f(x);
    for (int i = 0; i < 2; i++) {
        float y = float(i);
        x += y;
    }
    if (y > 0.0) {
        vec3 col = vec3(y * 0.1);
        fragColor = vec4(col, 1.0);
    } else
        fragColor = vec4(0.0);
}
