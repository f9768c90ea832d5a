/* ---
id = "camera.orbit"
slot = "camera"
summary = "Pinhole camera orbiting CAMERA_TARGET with iTime, or where a mouse drag puts it, looking at it"
provides = ["cameraRay"]
requires = []
params = { CAMERA_RADIUS = { type = "float", default = 3.0, range = [0.01, 1000.0] }, CAMERA_HEIGHT = { type = "float", default = 1.5 }, CAMERA_SPEED = { type = "float", default = 0.3 }, CAMERA_TARGET = { type = "vec3", default = [0.0, 0.0, 0.0] }, CAMERA_FOCAL = { type = "float", default = 1.5, range = [0.1, 100.0] }, CAMERA_ROLL = { type = "float", default = 0.0, range = [-3.1415927, 3.1415927] }, CAMERA_START = { type = "float", default = 0.0 } }
sources = ["lighting-model skill, complete code template (main function)"]
formula = '\boldsymbol{\omega} = \operatorname{normalize}(u\, \mathbf{u} + v\, \mathbf{v} + f\, \mathbf{w}), \quad \mathbf{o} = \mathbf{t} + (R \cos\varphi,\ h,\ R \sin\varphi), \quad (\varphi, h) = \begin{cases} (2\pi\, m_x / \text{res}_x,\ 2 h_0\, m_y / \text{res}_y) & \text{after a drag} \\ (\varphi_0 + s\, \text{iTime},\ h_0) & \text{before} \end{cases}, \quad (u, v) = R(\rho) \frac{2\, \mathbf{x}_{\text{pixel}} - \mathbf{res}}{\text{res}_y}, \quad \mathbf{w} = \operatorname{normalize}(\mathbf{t} - \mathbf{o}), \quad \mathbf{u} = \begin{cases} \operatorname{normalize}(\mathbf{w} \times \hat{\mathbf{y}}) & w_x^2 + w_z^2 > 10^{-8} \\ \hat{\mathbf{x}} & \text{straight up or down} \end{cases}, \quad \mathbf{v} = \mathbf{u} \times \mathbf{w}'
--- */
// Screen coordinates span [-1, 1] vertically; CAMERA_FOCAL is the distance to that screen.
// A mouse drag orbits: ShaderToy keeps iMouse.xy where the button was last held and gives 0
// before any drag, so a render (no mouse) follows iTime and the picture does not change.
void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    // Roll (radians): the screen turns counterclockwise under the picture, which turns clockwise.
    float c = cos(CAMERA_ROLL);
    float r = sin(CAMERA_ROLL);
    uv = mat2(c, r, -r, c) * uv;
    float angle = CAMERA_START + iTime * CAMERA_SPEED;
    float height = CAMERA_HEIGHT;
    if (iMouse.x > 0.0 || iMouse.y > 0.0) {
        angle = 6.28318531 * iMouse.x / iResolution.x;
        height = 2.0 * CAMERA_HEIGHT * iMouse.y / iResolution.y;
    }
    ro = CAMERA_TARGET + vec3(CAMERA_RADIUS * cos(angle), height, CAMERA_RADIUS * sin(angle));
    vec3 ww = normalize(CAMERA_TARGET - ro);
    // Looking straight up or down, ww x y vanishes: the screen's x is then the world's, and
    // its up -z looking down (+z looking up), as for a camera tilted from looking along -z.
    vec3 uu = vec3(1.0, 0.0, 0.0);
    if (dot(ww.xz, ww.xz) > 1e-8) uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    rd = normalize(uv.x * uu + uv.y * vv + CAMERA_FOCAL * ww);
}
