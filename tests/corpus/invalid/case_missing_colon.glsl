// case label missing its colon
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    int k = int(fragCoord.x);
    switch (k) {
        case 0 fragColor = vec4(1.0); break;
        default: fragColor = vec4(0.0);
    }
}
