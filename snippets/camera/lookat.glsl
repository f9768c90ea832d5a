/* ---
id = "camera.lookat"
slot = "camera"
summary = "Fixed pinhole camera at CAMERA_POSITION looking at CAMERA_TARGET"
provides = ["cameraRay"]
requires = []
params = { CAMERA_POSITION = { type = "vec3", default = [0.0, 1.0, 4.0] }, CAMERA_TARGET = { type = "vec3", default = [0.0, 0.0, 0.0] }, CAMERA_FOCAL = { type = "float", default = 1.5, range = [0.1, 100.0] }, CAMERA_ROLL = { type = "float", default = 0.0, range = [-3.1415927, 3.1415927] } }
sources = ["lighting-model skill, complete code template (main function)"]
formula = '\boldsymbol{\omega} = \operatorname{normalize}(u\, \mathbf{u} + v\, \mathbf{v} + f\, \mathbf{w}), \quad (u, v) = R(\rho) \frac{2\, \mathbf{x}_{\text{pixel}} - \mathbf{res}}{\text{res}_y}, \quad \mathbf{w} = \operatorname{normalize}(\mathbf{t} - \mathbf{o}), \quad \mathbf{u} = \begin{cases} \operatorname{normalize}(\mathbf{w} \times \hat{\mathbf{y}}) & w_x^2 + w_z^2 > 10^{-8} \\ \hat{\mathbf{x}} & \text{straight up or down} \end{cases}, \quad \mathbf{v} = \mathbf{u} \times \mathbf{w}, \quad \mathbf{o} = \text{CAMERA\_POSITION}, \quad \mathbf{t} = \text{CAMERA\_TARGET}, \quad f = \text{CAMERA\_FOCAL}'
--- */
void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    // Roll (radians): the screen turns counterclockwise under the picture, which turns clockwise.
    float c = cos(CAMERA_ROLL);
    float r = sin(CAMERA_ROLL);
    uv = mat2(c, r, -r, c) * uv;
    ro = CAMERA_POSITION;
    vec3 ww = normalize(CAMERA_TARGET - ro);
    // Looking straight up or down, ww x y vanishes: the screen's x is then the world's, and
    // its up -z looking down (+z looking up), as for a camera tilted from looking along -z.
    vec3 uu = vec3(1.0, 0.0, 0.0);
    if (dot(ww.xz, ww.xz) > 1e-8) uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    rd = normalize(uv.x * uu + uv.y * vv + CAMERA_FOCAL * ww);
}
