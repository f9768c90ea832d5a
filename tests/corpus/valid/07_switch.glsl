vec3 pick(int k)
{
    vec3 c;
    switch (k) {
        case 0:
            c = vec3(1.0, 0.2, 0.2);
            break;
        case 1:
        case 2:
            c = vec3(0.2, 1.0, 0.2);
            break;
        default:
            c = vec3(0.2, 0.2, 1.0);
    }
    return c;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    int k = int(fragCoord.x / iResolution.x * 4.0);
    fragColor = vec4(pick(k), 1.0);
}
