"""`cameraPath(t, eye, target)`: a path camera's keyframes as GLSL, the curve camera.path flies.

Between keys i and i+1 the eye and the target follow a uniform Catmull-Rom spline through the
keys before and after (the end keys repeat at an open path's ends; a looping path wraps round
and closes through its first key again, one segment after the last key, as long as the first
segment). A Catmull-Rom spline passes through every key with a continuous tangent, so the
camera neither stops nor turns sharply at a key.
"""

from __future__ import annotations

from glint.compiler.catalog.loader import glsl_float, glsl_value
from glint.compiler.compose.units import Unit, generated
from glint.compiler.scene.model import PathCamera

CAMERA_PATH = "cameraPath"


def path_unit(camera: PathCamera) -> Unit:
    keys = camera.keys
    n = len(keys)
    times = [key.time for key in keys]
    if camera.loop:
        period = times[-1] + (times[1] - times[0]) - times[0]
        times.append(times[0] + period)  # the closing segment back to the first key
    segments = len(times) - 1

    def key(i: int) -> int:
        if camera.loop:
            return i % n
        return min(max(i, 0), n - 1)

    def point(i: int, field: str) -> str:
        return glsl_value(getattr(keys[key(i)], field), "vec3")

    lines = [
        f"// camera.path: the eye and the point it looks at at time t, on a Catmull-Rom curve "
        f"through the {n} keys.",
        f"void {CAMERA_PATH}(float t, out vec3 eye, out vec3 target) {{",
    ]
    start = glsl_float(times[0])
    if camera.loop:
        lines.append(f"    t = {start} + mod(t - {start}, {glsl_float(times[-1] - times[0])});")
    else:
        lines.append(f"    t = clamp(t, {start}, {glsl_float(times[-1])});")
    for s in range(segments):
        t0, t1 = times[s], times[s + 1]
        test = "    if" if s == 0 else "    else if"
        condition = f"(t <= {glsl_float(t1)})" if s < segments - 1 else ""
        head = f"{test} {condition} {{" if condition else "    else {"
        if segments == 1:
            head = "    {"
        u = f"(t - {glsl_float(t0)}) / {glsl_float(t1 - t0)}"
        lines += [
            head,
            f"        float u = {u};",
            f"        eye = catmullRom({point(s - 1, 'position')}, {point(s, 'position')}, "
            f"{point(s + 1, 'position')}, {point(s + 2, 'position')}, u);",
            f"        target = catmullRom({point(s - 1, 'target')}, {point(s, 'target')}, "
            f"{point(s + 1, 'target')}, {point(s + 2, 'target')}, u);",
            "    }",
        ]
    lines.append("}")
    spline = """// Uniform Catmull-Rom from b (u = 0) to c (u = 1); a and d lie beside them.
vec3 catmullRom(vec3 a, vec3 b, vec3 c, vec3 d, float u) {
    return 0.5 * (2.0 * b + (c - a) * u + (2.0 * a - 5.0 * b + 4.0 * c - d) * u * u
                  + (3.0 * (b - c) + d - a) * u * u * u);
}

"""
    body = spline + "\n".join(lines) + "\n"
    return generated("scene.camera_path", ["catmullRom", CAMERA_PATH], [], body)
