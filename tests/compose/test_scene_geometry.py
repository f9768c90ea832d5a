"""The scene language's geometry: placed objects, CSG groups, repetition, and the user's own
distance function in a GLSL file. Distances are evaluated from the composed shader's own GLSL
(glint's evaluator, float32) and compared with float64 values worked out here."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

import glint
from glint.compiler.cli import main
from glint.compiler.compose.codegen.field_code import rotation_matrix
from glint.compiler.errors import InputError
from glint.compiler.evaluator.api import evaluate
from glint.compiler.scene.model import scene_from_dict

UNIFORMS = {"iTime": 0.0, "iResolution": np.array([64.0, 36.0, 1.0]), "iMouse": np.zeros(4)}
MATERIALS = {"a": {"albedo": [0.8, 0.8, 0.8]}, "b": {"albedo": [0.2, 0.4, 0.8]}}
LIGHT = [{"type": "directional", "direction": [0.4, 0.8, 0.3]}]


def _scene(objects: list[dict], **more: object) -> dict:
    return {"name": "t", "objects": objects, "materials": MATERIALS, "lights": LIGHT, **more}


def _library(shader: glint.Shader) -> str:
    """Every unit but mainImage: what the evaluator runs `map` and `raymarch` from."""
    return "\n".join(u.body for u in shader.units if "mainImage" not in u.provides)


def _field(scene: dict, points: np.ndarray, function: str = "map") -> np.ndarray:
    shader = glint.compose(scene_from_dict(scene))
    p = points.astype(np.float32)
    return np.asarray(evaluate(_library(shader), function, [p], externals=UNIFORMS), float)


def _box(p: np.ndarray, half: np.ndarray) -> np.ndarray:
    q = np.abs(p) - half
    return np.linalg.norm(np.maximum(q, 0.0), axis=-1) + np.minimum(q.max(axis=-1), 0.0)


def _sphere(p: np.ndarray, r: float) -> np.ndarray:
    return np.linalg.norm(p, axis=-1) - r


POINTS = np.random.default_rng(7).uniform(-2.5, 2.5, size=(400, 3))


def test_rotation_order_is_x_then_y_then_z_about_fixed_axes() -> None:
    r = np.array(rotation_matrix([90.0, 90.0, 0.0]))
    # y turns to z about x, then z turns to x about y
    assert np.allclose(r @ [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], atol=1e-12)
    r = np.array(rotation_matrix([0.0, 0.0, 90.0]))
    assert np.allclose(r @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-12)
    assert np.allclose(np.array(rotation_matrix([30.0, -50.0, 70.0])) @ np.array(
        rotation_matrix([30.0, -50.0, 70.0])).T, np.eye(3), atol=1e-12)  # fmt: skip


def test_a_placed_box_keeps_an_exact_distance_under_rotation_and_scale() -> None:
    obj = {"shape": "box", "size": [1.0, 0.5, 0.25], "position": [0.5, -0.25, 0.0],
           "rotation": [20.0, 35.0, -60.0], "scale": 1.5, "material": "a"}  # fmt: skip
    got = _field(_scene([obj]), POINTS)
    r = np.array(rotation_matrix(obj["rotation"]))  # type: ignore[arg-type]
    local = (POINTS - obj["position"]) @ r / 1.5  # Rᵀ · (p - position) / scale, row-wise
    want = 1.5 * _box(local, np.array(obj["size"]))
    assert np.max(np.abs(got - want)) < 1e-4


def _sharp(shape: str, blend: float = 0.0) -> dict:
    return {
        "shape": shape, "blend": blend, "material": "a",
        "children": [{"shape": "box", "size": [1.0, 0.6, 0.8]},
                     {"shape": "sphere", "radius": 0.8, "position": [0.6, 0.5, 0.0]}],
    }  # fmt: skip


def _parts() -> tuple[np.ndarray, np.ndarray]:
    return _box(POINTS, np.array([1.0, 0.6, 0.8])), _sphere(POINTS - [0.6, 0.5, 0.0], 0.8)


@pytest.mark.parametrize(
    ("shape", "combine"),
    [("union", np.minimum), ("intersection", np.maximum),
     ("subtraction", lambda a, b: np.maximum(a, -b))],
)  # fmt: skip
def test_csg_groups_put_points_inside_and_outside_as_their_sets_do(shape: str, combine) -> None:
    a, b = _parts()
    want = combine(a, b)
    got = _field(_scene([_sharp(shape)]), POINTS)
    assert np.max(np.abs(got - want)) < 1e-4
    # and the sign is the set operation's: inside the union is inside either part, ...
    inside = {"union": (a < 0) | (b < 0), "intersection": (a < 0) & (b < 0),
              "subtraction": (a < 0) & (b >= 0)}[shape]  # fmt: skip
    clear = np.abs(want) > 1e-3
    assert np.array_equal((got < 0)[clear], inside[clear])


@pytest.mark.parametrize("shape", ["union", "intersection", "subtraction"])
def test_smooth_groups_differ_from_sharp_only_within_the_blend_radius(shape: str) -> None:
    blend = 0.3
    a, b = _parts()
    sharp = _field(_scene([_sharp(shape)]), POINTS)
    smooth = _field(_scene([_sharp(shape, blend)]), POINTS)
    other = b if shape != "subtraction" else -b
    near = np.abs(a - other) < blend
    assert np.max(np.abs(smooth - sharp)) <= blend / 4 + 1e-5
    assert np.max(np.abs(smooth - sharp)[~near]) < 1e-5
    assert np.max(np.abs(smooth - sharp)[near]) > 1e-3  # the blend does something
    if shape == "union":  # a smooth union only adds material
        assert np.all(smooth <= sharp + 1e-6)


def test_groups_nest_and_take_their_own_placement() -> None:
    inner = _sharp("subtraction")
    inner.pop("material")
    top = {"shape": "sphere", "radius": 0.3, "position": [0, 2, 0]}
    outer = {"shape": "union", "material": "a", "position": [0.0, 1.0, 0.0], "scale": 0.5,
             "children": [inner, top]}  # fmt: skip
    got = _field(_scene([outer]), POINTS)
    local = (POINTS - [0.0, 1.0, 0.0]) / 0.5
    a = _box(local, np.array([1.0, 0.6, 0.8]))
    b = _sphere(local - [0.6, 0.5, 0.0], 0.8)
    want = 0.5 * np.minimum(np.maximum(a, -b), _sphere(local - [0, 2, 0], 0.3))
    assert np.max(np.abs(got - want)) < 1e-4


def test_repeat_places_count_copies_spacing_apart_and_no_more() -> None:
    row = {"shape": "repeat", "spacing": [2.0, 0.0, 0.0], "count": [3, 1, 1], "material": "a",
           "children": [{"shape": "sphere", "radius": 0.5}]}  # fmt: skip
    points = np.array([[-2.0, 0, 0], [0.0, 0, 0], [2.0, 0, 0], [4.0, 0, 0], [1.0, 0, 0]])
    got = _field(_scene([row]), points)
    assert np.allclose(got, [-0.5, -0.5, -0.5, 1.5, 0.5], atol=1e-5)


def test_a_part_of_a_group_cannot_take_a_material_of_its_own() -> None:
    group = _sharp("union")
    group["children"][0]["material"] = "b"  # type: ignore[index]
    with pytest.raises(InputError, match="part 1 .* has a material"):
        scene_from_dict(_scene([group]))


# --- the user's own distance function ---------------------------------------------------------


def _user_scene(tmp_path: Path, glsl: str, **geometry: object) -> Path:
    (tmp_path / "field.glsl").write_text(glsl, encoding="utf-8")
    extra = "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in geometry.items())
    scene = tmp_path / "scene.toml"
    scene.write_text(
        '[geometry]\nfile = "field.glsl"\nmaterial = "rock"\n' + extra
        + '[materials.rock]\nalbedo = [0.5, 0.4, 0.3]\n'
        + '[[lights]]\ntype = "directional"\ndirection = [0.3, 0.8, 0.2]\n',
        encoding="utf-8",
    )  # fmt: skip
    return scene


# A sphere's distance, doubled: a field with Lipschitz constant 2.
DOUBLED = "float sceneDistance(vec3 p) { return 2.0 * (length(p) - 1.0); }\n"


def test_a_lipschitz_bound_of_2_makes_the_march_take_the_smaller_steps(tmp_path: Path) -> None:
    ro, rd = np.array([[0.0, 0.0, -3.0]]), np.array([[0.0, 0.0, 1.0]])
    hits = []
    for bound in (1.0, 2.0):
        shader = glint.compose(_user_scene(tmp_path, DOUBLED, lipschitz=bound))
        args = [ro.astype(np.float32), rd.astype(np.float32)]
        hits.append(float(evaluate(_library(shader), "raymarch", args, externals=UNIFORMS)[0]))
    # Trusting the doubled field, the first step (4) jumps over the sphere to its far side;
    # divided by its bound, the march stops at the near surface, 2 units away.
    assert abs(hits[0] - 4.0) < 1e-3
    assert abs(hits[1] - 2.0) < 1e-2


def test_user_geometry_is_planned_as_a_marched_field_and_pruned(tmp_path: Path) -> None:
    glsl = DOUBLED + "float unused(vec3 p) { return 0.0; }\n"
    shader = glint.compose(_user_scene(tmp_path, glsl, lipschitz=2.0))
    for slot in ("raymarch", "normal", "shadow"):
        assert slot in shader.plan.choices
    assert "sceneDistance(p) / 2.0" in shader.text
    assert "unused" not in shader.text  # only what mainImage reaches is emitted
    assert shader.validate() == []


def test_a_compile_error_is_reported_at_the_user_file_and_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    glsl = "// my field\n\nfloat sceneDistance(vec3 p) {\n    return vec2(1.0);\n}\n"
    scene = _user_scene(tmp_path, glsl)
    out = tmp_path / "out.glsl"
    # compose compiles what it writes: the error at the user's line, nothing written
    assert main(["compose", str(scene), "-o", str(out)]) == 1
    assert "field.glsl:4:" in capsys.readouterr().err and not out.exists()
    # written anyway on request, `glint validate` finds it at the same line
    assert main(["compose", str(scene), "-o", str(out), "--no-validate"]) == 0
    assert main(["validate", str(out)]) == 1
    assert "field.glsl:4:" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("glsl", "message"),
    [
        ("float sceneDistance(vec3 p) {\n  return length(p) - 1.0\n}\n", r"field.glsl:3:1: syntax"),
        ("float map(vec3 p) { return 0.0; }\nfloat sceneDistance(vec3 p) { return map(p); }\n",
         r"field.glsl:1: `map` is also a function of glint's generated scene code"),
        ("float sdBox(vec3 p, vec3 b) { return 0.0; }\n"
         "float sceneDistance(vec3 p) { return sdBox(p, vec3(1.0)); }\n",
         r"field.glsl:1: `sdBox` is also defined by the catalog's sdf.box"),
        ("float sceneDistance(vec3 p) {\n  return length(p) - wobble(p);\n}\n",
         r"field.glsl:1: calls `wobble`, which neither the file nor glint's catalog defines"),
        ("float distance2(vec3 p) { return 0.0; }\n", r"defines no `float sceneDistance"),
        ("float sceneDistance(vec2 p) { return 0.0; }\n", r"glint calls it as float sceneDistance"),
    ],
)  # fmt: skip
def test_bad_user_geometry_gets_one_clear_message_and_exit_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], glsl: str, message: str
) -> None:
    scene = _user_scene(tmp_path, glsl)
    out = tmp_path / "out.glsl"
    assert main(["compose", str(scene), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1, err
    assert re.search(message, err), err
    assert not out.exists()  # nothing half-written


def test_the_user_file_may_use_the_scene_constants(tmp_path: Path) -> None:
    glsl = DOUBLED + "vec3 sceneAlbedo(vec3 p, int id, vec3 a) { return a * SUN_DIR.y; }\n"
    assert glint.compose(_user_scene(tmp_path, glsl)).validate() == []


def test_a_missing_user_file_names_where_it_was_looked_for(tmp_path: Path) -> None:
    scene = _user_scene(tmp_path, DOUBLED)
    (tmp_path / "field.glsl").unlink()
    with pytest.raises(InputError, match=r"geometry.file: field.glsl: no such file"):
        glint.compose(scene)


def test_materials_by_the_id_the_user_code_returns(tmp_path: Path) -> None:
    glsl = DOUBLED + "int sceneMaterial(vec3 p) { return p.y > 0.0 ? 7 : 3; }\n"
    (tmp_path / "field.glsl").write_text(glsl, encoding="utf-8")
    scene = tmp_path / "scene.toml"
    scene.write_text(
        '[geometry]\nfile = "field.glsl"\n[geometry.materials]\n3 = "rock"\n7 = "moss"\n'
        '[materials.rock]\nalbedo = [0.5, 0.4, 0.3]\n[materials.moss]\nalbedo = [0.1, 0.5, 0.1]\n',
        encoding="utf-8",
    )  # fmt: skip
    shader = glint.compose(scene)
    points = np.array([[0.0, 1.0, 0.0], [0.0, -1.0, 0.0]], dtype=np.float32)
    got = evaluate(_library(shader), "materialAt", [points], externals=UNIFORMS)
    order = shader.scene.used_materials()
    assert [order[i] for i in np.asarray(got)] == ["moss", "rock"]


def test_split_common_gives_a_common_tab_without_uniforms_and_the_same_picture(
    tmp_path: Path,
) -> None:
    shader = glint.compose(None)
    tabs = shader.split_common()
    assert "mainImage" in tabs.image and "mainImage" not in tabs.common
    # ShaderToy declares the uniforms after the Common tab: it must compile without them.
    alone = tmp_path / "common.frag"
    alone.write_text("#version 300 es\nprecision highp float;\n" + tabs.common
                     + "\nout vec4 o;\nvoid main() { o = vec4(0.0); }\n")  # fmt: skip
    run = subprocess.run(["glslangValidator", str(alone)], capture_output=True, text=True)
    assert run.returncode == 0, run.stdout
    joined = tabs.common + "\n" + tabs.image
    whole = glint.render(shader, size=(96, 54), time=1.0).pixels
    split = glint.render(joined, size=(96, 54), time=1.0).pixels
    assert np.array_equal(whole, split)


def test_the_plan_says_when_the_field_is_only_a_bound(tmp_path: Path) -> None:
    exact = glint.compose(scene_from_dict(_scene([{"shape": "torus", "material": "a"}])))
    assert "bound" not in exact.plan.reasons["raymarch"]
    for scene in (_scene([_sharp("union", 0.2)]),
                  _scene([{"shape": "ellipsoid", "material": "a"}])):  # fmt: skip
        assert (
            "not an exact distance"
            in glint.compose(scene_from_dict(scene)).plan.reasons["raymarch"]
        )
    user = glint.compose(_user_scene(tmp_path, DOUBLED, lipschitz=2.0))
    assert "not an exact distance" in user.plan.reasons["raymarch"]


# A biconcave disc (a red blood cell) of radius `SIZE`: an ellipse revolved, its faces carved
# by two spheres with a smooth blend. Thin and concave: rays graze the dimple's rim.
CELL = """float cellUnit(vec3 p) {
    vec2 q = vec2(length(p.xz), p.y);
    float disc = (length(q / vec2(1.0, 0.35)) - 1.0) * 0.35;
    float dimples = min(length(p - vec3(0.0, 0.55, 0.0)), length(p + vec3(0.0, 0.55, 0.0))) - 0.5;
    float h = clamp(0.5 - 0.5 * (disc + dimples) / 0.15, 0.0, 1.0);
    return mix(disc, -dimples, h) + 0.15 * h * (1.0 - h);
}
float sceneDistance(vec3 p) {
    return SIZE * cellUnit(p / SIZE);
}
"""


def _largest_run(mask: np.ndarray) -> int:
    """The most pixels of `mask` joined by their edges or corners: a line is many, a pixel
    where two pictures show different sides of a rim is one or two."""
    seen = np.zeros_like(mask)
    largest = 0
    for start in zip(*np.nonzero(mask), strict=True):
        if seen[start]:
            continue
        seen[start] = True
        stack, size = [start], 0
        while stack:
            y, x = stack.pop()
            size += 1
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    near = (y + dy, x + dx)
                    inside = 0 <= near[0] < mask.shape[0] and 0 <= near[1] < mask.shape[1]
                    if inside and mask[near] and not seen[near]:
                        seen[near] = True
                        stack.append(near)
        largest = max(largest, size)
    return largest


@pytest.mark.render
@pytest.mark.parametrize(
    ("size", "position", "focal"),
    [
        (1.0, "[0.0, 4.0, 5.0]", 5.0),  # a long lens: the pixel cone was 2 pixels wide
        (10.0, "[0.0, 24.0, 30.0]", 1.5),  # far and large: the hit 0.06 off, the shadow at 0.02
    ],
    ids=["long-lens", "far-and-large"],
)
def test_a_concave_field_shows_no_hairline_at_any_tier(
    tmp_path: Path, size: float, position: str, focal: float
) -> None:
    """Issue 28: dark hairlines in a biconcave cell's dimple at balanced and fast. Two causes,
    both fixed where they arise for every marcher: through a long lens the pixel-cone march's
    tolerance, an angle fixed for focal 1.5, was two pixels wide, and the dimple's rim caught
    rays meant for its floor (now baked for the lens: 18 joined dark pixels before); far away,
    a hit accepted up to the cone's radius (0.06 at 30 units) shadowed itself from a shadow ray
    that starts 0.02 along the light (now shadow rays start the march's tolerance out along the
    normal, marchTolerance: 42 joined dark pixels without it). Against the reference tier no
    dark line is left inside the cell, and outliers stay rare."""
    (tmp_path / "cell.glsl").write_text(CELL.replace("SIZE", repr(size)))
    scene = tmp_path / "cell.toml"
    half = [1.1 * size, 0.5 * size]
    scene.write_text(
        f'[camera]\ntype = "lookat"\nposition = {position}\ntarget = [0.0, 0.0, 0.0]\n'
        f"focal = {focal}\n"
        '[geometry]\nfile = "cell.glsl"\nmaterial = "cell"\nlipschitz = 1.5\n'
        f"bounds = [[{-half[0]}, {-half[1]}, {-half[0]}], [{half[0]}, {half[1]}, {half[0]}]]\n"
        "[materials.cell]\nalbedo = [0.7, 0.05, 0.04]\nroughness = 0.4\n"
        '[[lights]]\ntype = "directional"\ndirection = [0.9, 0.35, 0.2]\nintensity = 3.0\n'
        f"shadow_distance = {6.0 * size}\n"
        '[[lights]]\ntype = "sky"\nintensity = 0.5\n'
    )
    pictures = {}
    for tier in ("reference", "balanced", "fast"):
        shader = glint.compose(scene, tier=tier)
        pictures[tier] = glint.render(shader, size=(640, 360), time=0.0).pixels
    reference = pictures["reference"]
    cell = (reference[..., 0] - reference[..., 2]) > 0.05
    inside = cell.copy()
    for _ in range(3):  # three pixels in from the silhouette
        inside &= np.roll(inside, 1, 0) & np.roll(inside, -1, 0)
        inside &= np.roll(inside, 1, 1) & np.roll(inside, -1, 1)
    assert inside.sum() > 5000
    luminance = reference.mean(axis=-1)
    for tier in ("balanced", "fast"):
        seen = pictures[tier].mean(axis=-1)
        dark = (seen < luminance - 0.08) & inside
        assert _largest_run(dark) < 5, f"{tier}: a dark line of {_largest_run(dark)} pixels"
        outliers = ((seen < 0.5 * luminance) | (seen > 2.0 * luminance)).mean()
        assert outliers < 0.004, f"{tier}: {outliers:.2%} outliers"


def test_every_name_the_file_shares_with_glint_is_reported_at_once(tmp_path: Path) -> None:
    """Issue 28: a port from ShaderToy met its clashes one per run (`map`, then `sdBox`, then
    `PI` ...). One error now lists them all, each at its line; a helper the distance function
    never reaches (the port's old `diffuse`) is not one of them."""
    glsl = (
        "float map(vec3 p) { return length(p) - 1.0; }\n"
        "float sdBox(vec3 p, vec3 b) { return 0.0; }\n"
        "#define PI 3.14159\n"
        "float diffuse(float x) { return x / PI; }\n"
        "float sceneDistance(vec3 p) { return map(p) + sdBox(p, vec3(PI)); }\n"
    )
    with pytest.raises(InputError) as raised:
        glint.compose(_user_scene(tmp_path, glsl))
    message = str(raised.value)
    assert "3 names are glint's as well" in message
    assert "diffuse" not in message
    assert "field.glsl:1: `map` is also a function of glint's generated scene code" in message
    assert "field.glsl:2: `sdBox` is also defined by the catalog's sdf.box" in message
    assert "`PI` is also defined by the catalog's core.constants" in message


def test_a_helper_nothing_reaches_neither_clashes_nor_is_emitted(tmp_path: Path) -> None:
    """Left-overs of a port (its own `diffuse`, `PI`, `calcNormal`) that sceneDistance never
    calls: the scene composes, the shader compiles (glslang, as compose runs it) with the
    catalog's `diffuse` and `PI`, and none of the left-overs is in it."""
    glsl = (
        "const float PI = 3.0;\n"
        "float diffuse(float x) { return x / PI; }\n"
        "vec3 calcNormal(vec3 p) { return vec3(0.0, 1.0, 0.0); }\n"
        "float blob(vec3 p) { return length(p) - 1.0; }\n"
        "float sceneDistance(vec3 p) { return blob(p); }\n"
    )
    shader = glint.compose(_user_scene(tmp_path, glsl))
    assert shader.validate() == []
    assert "float blob(vec3 p)" in shader.text
    assert "x / PI" not in shader.text and "const float PI = 3.0" not in shader.text
    assert "return vec3(0.0, 1.0, 0.0)" not in shader.text
