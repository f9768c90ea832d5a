"""The normal variants against the exact normals of reference SDF scenes, in degrees.

Gradient-based variants (they tap `map`) are probed point-wise on the GPU with the reference
scene's GLSL as `map`, at points on each surface and near the box's edges. The derivative-based
flat normal needs neighbouring pixels, so it is rendered: a camera looks at a rotated box over a
ground plane, each pixel writes its normal, and the pixels well inside a flat face are compared
with that face's normal. Each variant is held to the `max_deg` / `mean_deg` of its front matter.
"""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog import Snippet, load_catalog
from glint.compiler.glslang import validate
from glint.compiler.probes import run_probe
from glint.compiler.references.normals import (
    BOX_HALF,
    SCENES,
    angle_deg,
    box_edge_points,
    box_surface,
)
from glint.compiler.render import render
from glint.compiler.standalone import standalone_source

pytestmark = pytest.mark.render

CATALOG = load_catalog()
NORMALS = sorted(s.id for s in CATALOG.in_slot("normal"))
# Variants that estimate the SDF's gradient from taps of map(); probed point by point.
GRADIENT = [i for i in NORMALS if "map" in CATALOG.snippets[i].requires]
SAMPLES = 400


def tap_reach(snippet: Snippet) -> float:
    return float(snippet.params["NORMAL_EPS"].default)


def probe_normals(snippet_id: str, scene: str, points: np.ndarray) -> np.ndarray:
    inputs = {f"p{axis}": points[:, axis] for axis in range(3)}
    return run_probe(snippet_id, inputs, CATALOG, scene_stub=SCENES[scene].glsl)


def surface_points(snippet: Snippet, scene: str) -> np.ndarray:
    """Float64 points on the surface, rounded to the float32 the GPU receives (the reference is
    then taken at the same points, so what is measured is the variant, not the rounding)."""
    rng = np.random.default_rng(17)
    if scene == "box":
        # Faces at least two tap reaches from every edge, and rows of points at 2, 5 and 10
        # reaches from each edge: where no tap crosses an edge the box is a plane to the taps.
        reach = tap_reach(snippet)
        faces = box_surface(rng, SAMPLES, margin=2.0 * reach)
        points = np.concatenate([faces, box_edge_points(np.array([2.0, 5.0, 10.0]) * reach)])
    else:
        points = SCENES[scene].surface(rng, SAMPLES)
    return points.astype(np.float32).astype(np.float64)


@pytest.mark.parametrize("scene", sorted(SCENES))
@pytest.mark.parametrize("snippet_id", GRADIENT)
def test_gradient_normal_within_its_budget(snippet_id: str, scene: str) -> None:
    snippet = CATALOG.snippets[snippet_id]
    points = surface_points(snippet, scene)
    gpu = probe_normals(snippet_id, scene, points).astype(np.float64)
    assert np.isfinite(gpu).all()
    np.testing.assert_allclose(np.linalg.norm(gpu, axis=1), 1.0, atol=1e-5)
    error = angle_deg(gpu, SCENES[scene].normal(points))
    worst = points[np.argmax(error)].tolist()
    budget = snippet.error_budget
    assert error.max() <= budget["max_deg"], f"max {error.max():.3g} deg at {worst}"
    assert error.mean() <= budget["mean_deg"], f"mean {error.mean():.3g} deg"


@pytest.mark.parametrize("snippet_id", GRADIENT)
def test_gradient_normal_near_an_edge_still_faces_out(snippet_id: str) -> None:
    # Closer to a box edge than the taps reach, the estimate blends the two faces (the edge
    # shades as if rounded over about NORMAL_EPS). It must stay finite and on the outer side of
    # the face it belongs to, never tip into the solid.
    reach = tap_reach(CATALOG.snippets[snippet_id])
    points = box_edge_points(np.array([0.0, 0.1, 0.5, 0.9]) * reach)
    points = points.astype(np.float32).astype(np.float64)
    gpu = probe_normals(snippet_id, "box", points).astype(np.float64)
    face = SCENES["box"].normal(points)
    assert np.isfinite(gpu).all()
    assert (angle_deg(gpu, face) < 60.0).all()


# --- the derivative-based flat normal, rendered ---------------------------------------------

WIDTH, HEIGHT = 160, 120
EYE = np.array([3.0, 2.2, 4.0])
TARGET = np.array([0.0, -0.2, 0.0])
FOCAL = 1.5
YAW = 0.5  # radians: the box is turned about y so that no face is axis-aligned on screen
GROUND_Y = -1.2



def vec3(v: np.ndarray) -> str:
    return "vec3(" + ", ".join(repr(float(x)) for x in v) + ")"


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
    vec3 n = calcNormal(EYE + max(t, 0.0) * rd);
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


def flat_shader() -> str:
    snippet = CATALOG.get("normal.derivative_flat")
    return standalone_source(snippet, CATALOG, FLAT_SCENE_GLSL)


def test_derivative_flat_normal_validates() -> None:
    errors = [d for d in validate(flat_shader(), "flat.glsl", "shadertoy") if d.severity == "error"]
    assert [str(e) for e in errors] == []


def test_derivative_flat_normal_on_flat_faces() -> None:
    snippet = CATALOG.get("normal.derivative_flat")
    face, exact = flat_scene_reference()
    mask = interior(face)
    # Every face in view is measured on a fair number of pixels: the scene is what it claims.
    seen = {int(f): int((mask & (face == f)).sum()) for f in np.unique(face[face >= 0])}
    assert len(seen) >= 4 and min(seen.values()) >= 50, seen
    image = render(flat_shader(), WIDTH, HEIGHT)
    hit = image[..., 3] > 0.0
    assert (hit == (face >= 0))[mask].all()
    error = angle_deg(image[..., :3][mask].astype(np.float64), exact[mask])
    budget = snippet.error_budget
    assert error.max() <= budget["max_deg"], f"max {error.max():.3g} deg"
    assert error.mean() <= budget["mean_deg"], f"mean {error.mean():.3g} deg"
