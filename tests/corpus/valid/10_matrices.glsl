mat3 lookAt(vec3 ro, vec3 ta, float roll)
{
    vec3 cw = normalize(ta - ro);
    vec3 cp = vec3(sin(roll), cos(roll), 0.0);
    vec3 cu = normalize(cross(cw, cp));
    vec3 cv = cross(cu, cw);
    return mat3(cu, cv, cw);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    mat2x3 a = mat2x3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    mat3x2 b = transpose(a);
    mat2 c = b * a;
    mat4 m = mat4(1.0);
    m[3] = vec4(1.0, 2.0, 3.0, 1.0);
    mat3 cam = lookAt(vec3(0.0, 1.0, -3.0), vec3(0.0), 0.0);
    vec2 uv = fragCoord / iResolution.xy;
    vec3 rd = cam * normalize(vec3(uv - 0.5, 1.0));
    float d = determinant(c) + inverse(m)[3][0] + matrixCompMult(c, c)[0][0];
    fragColor = vec4(rd * 0.5 + 0.5 + d * 0.0, 1.0);
}
