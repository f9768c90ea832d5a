"""The derivative-based flat normal, rendered: it needs neighbouring pixels, so it cannot be
probed point by point. A camera looks at a rotated box over a ground plane, each pixel writes
its normal, and the pixels well inside a flat face are compared with that face's normal.

The probe test (tests/verify/test_normal_probes.py) and the benchmark both measure it here.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.catalog.loader import Catalog
from glint.compiler.compose.linking.standalone import standalone_source
from glint.compiler.render import render
from glint.compiler.verify.references.normals import BOX_HALF, angle_deg

FLAT_ID = "normal.derivative_flat"
WIDTH, HEIGHT = 160, 120
EYE = np.array([3.0, 2.2, 4.0])
TARGET = np.array([0.0, -0.2, 0.0])
FOCAL = 1.5
YAW = 0.5  # radians: the box is turned about y so that no face is axis-aligned on screen
GROUND_Y = -1.2


def vec3(v: np.ndarray) -> str:
    return "vec3(" + ", ".join(repr(float(x)) for x in v) + ")"


# The scene's distance, for the taps the variant takes where a pixel quad straddles two surfaces.
FLAT_MAP_GLSL = f"""
float map(vec3 p) {{
    float c = cos({YAW!r}), s = sin({YAW!r});
    vec3 q = abs(mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * p) - {vec3(BOX_HALF)};
    float box = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
    return min(box, p.y - ({GROUND_Y!r}));
}}
int materialAt(vec3 p) {{ return 0; }}
"""

FLAT_SCENE_GLSL = f"""
const vec3 EYE = {vec3(EYE)};
const vec3 TARGET = {vec3(TARGET)};
const vec3 BOX_HALF = {vec3(BOX_HALF)};
// World to box space: a turn of YAW about y.
mat3 toBox() {{
    float c = cos({YAW!r}), s = sin({YAW!r});
    return mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
}}
// Nearest hit of the rotated box (slabs) or the ground plane; -1 for none.
float intersectScene(vec3 ro, vec3 rd) {{
    vec3 o = toBox() * ro, d = toBox() * rd;
    vec3 t1 = (-BOX_HALF - o) / d, t2 = (BOX_HALF - o) / d;
    vec3 tn = min(t1, t2), tf = max(t1, t2);
    float tNear = max(max(tn.x, tn.y), tn.z), tFar = min(min(tf.x, tf.y), tf.z);
    float t = (tNear <= tFar && tNear > 0.0) ? tNear : -1.0;
    float tg = ({GROUND_Y!r} - ro.y) / rd.y;
    if (tg > 0.0 && (t < 0.0 || tg < t)) t = tg;
    return t;
}}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {{
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec3 ww = normalize(TARGET - EYE);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    vec3 rd = normalize(uv.x * uu + uv.y * vv + {FOCAL!r} * ww);
    float t = intersectScene(EYE, rd);
    // Every pixel computes p and its normal (uniform control flow), hit or not.
    // Rays that miss take a far point, as the composer's mainImage does (MARCH_FAR).
    vec3 n = calcNormal(EYE + (t > 0.0 ? t : 50.0) * rd);
    n = faceforward(n, rd, n);  // as the composer orients it
    fragColor = vec4(n, t);
}}
"""


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def flat_scene_reference() -> tuple[np.ndarray, np.ndarray]:
    """Per pixel (row 0 at the top, like the render): which face the ray hits (-1: nothing;
    0..5 the box's faces; 6 the ground) and that face's outward normal, in float64."""
    x = np.arange(WIDTH) + 0.5
    y = np.arange(HEIGHT)[::-1] + 0.5  # fragCoord.y grows upward
    fx, fy = np.meshgrid(x, y)
    uv = np.stack([2.0 * fx - WIDTH, 2.0 * fy - HEIGHT], axis=-1) / HEIGHT
    ww = _unit(TARGET - EYE)
    uu = _unit(np.cross(ww, [0.0, 1.0, 0.0]))
    vv = np.cross(uu, ww)
    rd = _unit(uv[..., :1] * uu + uv[..., 1:] * vv + FOCAL * ww)
    c, s = np.cos(YAW), np.sin(YAW)
    to_box = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])  # GLSL's mat3 is by column
    o, d = to_box @ EYE, rd @ to_box.T
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (-BOX_HALF - o) / d, (BOX_HALF - o) / d
    tn, tf = np.minimum(t1, t2), np.maximum(t1, t2)
    t_near, t_far = tn.max(axis=-1), tf.min(axis=-1)
    box_hit = (t_near <= t_far) & (t_near > 0.0)
    axis = tn.argmax(axis=-1)
    side = np.where(np.take_along_axis(d, axis[..., None], -1)[..., 0] < 0.0, 1, 0)
    with np.errstate(divide="ignore"):
        t_ground = (GROUND_Y - EYE[1]) / rd[..., 1]
    ground_hit = (t_ground > 0.0) & (~box_hit | (t_ground < t_near))
    face = np.where(box_hit, 2 * axis + side, -1)
    face = np.where(ground_hit, 6, face)
    normals = np.zeros(face.shape + (3,))
    for axis_index in range(3):
        for side_index, sign in ((0, -1.0), (1, 1.0)):
            local = np.zeros(3)
            local[axis_index] = sign
            normals[face == 2 * axis_index + side_index] = to_box.T @ local  # box to world
    normals[face == 6] = (0.0, 1.0, 0.0)
    return face, normals


def interior(face: np.ndarray) -> np.ndarray:
    """Pixels whose 3x3 neighbourhood all hit the same face: any 2x2 quad that holds them lies
    on that face, whichever way the driver groups pixels and takes its derivatives."""
    padded = np.pad(face, 1, constant_values=-2)
    same = np.ones(face.shape, bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            same &= padded[1 + dy : 1 + dy + face.shape[0], 1 + dx : 1 + dx + face.shape[1]] == face
    return same & (face >= 0)


def flat_shader(catalog: Catalog) -> str:
    snippet = catalog.get(FLAT_ID)
    return standalone_source(snippet, catalog, FLAT_SCENE_GLSL, FLAT_MAP_GLSL)


def render_flat(catalog: Catalog) -> np.ndarray:
    """The scene rendered: per pixel the normal (rgb) and the distance to the hit (alpha)."""
    return render(flat_shader(catalog), WIDTH, HEIGHT)


def flat_normal_errors(image: np.ndarray) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """The rendered normal's error in degrees on the pixels well inside a flat face, and where
    each of those pixels is (its column and row, row 0 at the top, and the face it shows)."""
    face, exact = flat_scene_reference()
    mask = interior(face)
    error = angle_deg(image[..., :3][mask].astype(np.float64), exact[mask])
    rows, cols = np.nonzero(mask)
    where = {"x": cols.astype(np.float64), "y": rows.astype(np.float64)}
    return error, where | {"face": face[mask].astype(np.float64)}


def straddling(face: np.ndarray) -> np.ndarray:
    """Pixels on a surface with a pixel of another surface, or of the sky, among their 8
    neighbours, but not on a corner between two faces of the box (where the normal itself
    turns): a 2x2 quad that holds them may straddle a silhouette."""
    padded = np.pad(face, 1, constant_values=-1)
    across = np.zeros(face.shape, bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            other = padded[1 + dy : 1 + dy + face.shape[0], 1 + dx : 1 + dx + face.shape[1]]
            box_edge = (other >= 0) & (other < 6) & (face < 6)
            across |= (other != face) & ~box_edge
    return across & (face >= 0)
