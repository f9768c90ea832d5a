// The ShaderToy map() of the porting guide (porting.md) without its ground, which blob.toml
// makes a plane of the scene. The original built its screen's x as cross(up, forward), which
// mirrors x against glint's camera: x is negated here, and in blob.toml's camera and lights.
float sceneDistance(vec3 p) {
    p.x = -p.x;
    float ball = sdSphere(p - vec3(0.0, 0.5, 0.0), 0.5);
    float blob = sdSphere(p - vec3(0.5, 0.9, 0.2), 0.25);
    return opSmoothUnion(ball, blob, 0.25);
}
