/* ---
id = "camera.path"
slot = "camera"
summary = "Pinhole camera flown through the scene's keyframes (cameraPath at iTime), looking at the path's target"
provides = ["cameraRay"]
requires = ["cameraPath"]
params = { CAMERA_FOCAL = { type = "float", default = 1.5, range = [0.1, 100.0] }, CAMERA_ROLL = { type = "float", default = 0.0, range = [-3.1415927, 3.1415927] } }
sources = ["lighting-model skill, complete code template (main function)", "Catmull & Rom 1974, A class of local interpolating splines"]
formula = '\boldsymbol{\omega} = \operatorname{normalize}(u\, \mathbf{u} + v\, \mathbf{v} + f\, \mathbf{w}), \quad (\mathbf{o}, \mathbf{t}) = \operatorname{path}(\text{iTime}), \quad (u, v) = R(\rho) \frac{2\, \mathbf{x}_{\text{pixel}} - \mathbf{res}}{\text{res}_y}, \quad \mathbf{w} = \operatorname{normalize}(\mathbf{t} - \mathbf{o}), \quad \mathbf{u} = \operatorname{normalize}(\mathbf{w} \times \hat{\mathbf{y}}), \quad \mathbf{v} = \mathbf{u} \times \mathbf{w}'
--- */
// The eye and its target come from the scene's keyframes (cameraPath, generated from
// [[camera.keys]]); the basis is the look-at camera's.
void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    // Roll (radians): the screen turns counterclockwise under the picture, which turns clockwise.
    float c = cos(CAMERA_ROLL);
    float r = sin(CAMERA_ROLL);
    uv = mat2(c, r, -r, c) * uv;
    vec3 target;
    cameraPath(iTime, ro, target);
    vec3 ww = normalize(target - ro);
    // Looking straight up or down, ww x y vanishes: the screen's x is then the world's, and
    // its up -z looking down (+z looking up), as for a camera tilted from looking along -z.
    vec3 uu = vec3(1.0, 0.0, 0.0);
    if (dot(ww.xz, ww.xz) > 1e-8) uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    rd = normalize(uv.x * uu + uv.y * vv + CAMERA_FOCAL * ww);
}
