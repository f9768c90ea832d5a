precision mediump float;
precision highp int;

highp float hash12(highp vec2 p)
{
    highp vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    lowp vec3 col = vec3(hash12(fragCoord + iTime));
    mediump float g = 1.0 / 2.2;
    fragColor = vec4(pow(col, vec3(g)), 1.0);
}
