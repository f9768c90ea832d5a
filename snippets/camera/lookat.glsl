/* ---
id = "camera.lookat"
slot = "camera"
summary = "Fixed pinhole camera at CAMERA_POSITION looking at CAMERA_TARGET"
provides = ["cameraRay"]
requires = []
params = { CAMERA_POSITION = { type = "vec3", default = [0.0, 1.0, 4.0] }, CAMERA_TARGET = { type = "vec3", default = [0.0, 0.0, 0.0] }, CAMERA_FOCAL = { type = "float", default = 1.5, range = [0.1, 100.0] } }
sources = ["lighting-model skill, complete code template (main function)"]
--- */
void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    ro = CAMERA_POSITION;
    vec3 ww = normalize(CAMERA_TARGET - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    rd = normalize(uv.x * uu + uv.y * vv + CAMERA_FOCAL * ww);
}
