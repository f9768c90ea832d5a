"""Every value of a scene is checked in one place (compiler/scene/values.py): a number
that is not a finite float32, a direction float32 cannot normalise, groups nested past the
stated depth each get one InputError naming the key, the value and what was expected, and
every walk over a scene survives the deepest scene allowed."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from scene_inputs import base_scene, error

import glint
from glint.compiler.errors import InputError
from glint.compiler.scene.model import parse_scene, scene_from_dict
from glint.compiler.scene.values import MAX_GROUP_DEPTH

ROOT = Path(__file__).resolve().parents[2]


def _with_sphere(**keys: Any) -> dict[str, Any]:
    return base_scene(objects=[{"shape": "sphere", "material": "m", **keys}])


# --- numbers: finite float32 everywhere ---------------------------------------------------------


@pytest.mark.parametrize(
    ("data", "expected"),
    [
        (_with_sphere(radius=1e300), "objects[0].radius: 1e+300 is beyond float32's range"),
        (_with_sphere(radius=math.inf), "objects[0].radius: inf is not a finite number"),
        (_with_sphere(radius=math.nan), "objects[0].radius: nan is not a finite number"),
        (_with_sphere(position=[1e39, 0.0, 0.0]), "objects[0].position[0]: 1e+39 is beyond"),
        (_with_sphere(position=[10**40, 0, 0]), "objects[0].position[0]: 1000000000000000"),
        (_with_sphere(radius=1e-300), "objects[0].radius: 1e-300 is too small for float32"),
        (_with_sphere(radius=True), "objects[0].radius: input should be a valid number (got True)"),
        (_with_sphere(radius=-0.0), "objects[0].radius: input should be greater than 0"),
        (
            base_scene(lights=[{"type": "sky", "intensity": math.inf}]),
            "lights[0].intensity: inf is not a finite number",
        ),
        (
            base_scene(materials={"m": {"albedo": [0.5, 0.5, 0.5], "roughness": math.nan}}),
            "materials.m.roughness: nan is not a finite number",
        ),
        (
            base_scene(materials={"m": {"albedo": [0.5, 0.5, 0.5], "subsurface_g": -math.inf}}),
            "materials.m.subsurface_g: -inf is not a finite number",
        ),
        (
            base_scene(
                objects=[
                    {
                        "shape": "repeat",
                        "material": "m",
                        "count": [2**70, 1, 1],
                        "spacing": [1.0, 0.0, 0.0],
                        "children": [{"shape": "sphere"}],
                    }
                ]
            ),
            "objects[0].count[0]: input should be less than or equal to 16777216",
        ),
        (
            base_scene(
                objects=[
                    {
                        "shape": "repeat",
                        "material": "m",
                        "count": [True, 1, 1],
                        "spacing": [1.0, 0.0, 0.0],
                        "children": [{"shape": "sphere"}],
                    }
                ]
            ),
            "objects[0].count[0]: input should be a valid integer (got True)",
        ),
        (base_scene(camera={"type": "orbit", "focal": 10**400}), "camera.focal: 1000000000"),
    ],
    ids=lambda v: v if isinstance(v, str) else "",
)
def test_a_number_that_is_not_a_finite_float32_names_key_value_and_expectation(
    data: dict[str, Any], expected: str
) -> None:
    message = error(data)
    assert message.startswith(f"scene.toml: {expected}"), message
    assert len(message) < 400  # a 400-digit integer is shortened, not printed whole


def test_toml_inf_nan_and_huge_integers_are_refused_by_key() -> None:
    base = '[[objects]]\nshape = "sphere"\nmaterial = "m"\n[materials.m]\n'
    for value, expected in [
        ("inf", "inf is not a finite number"),
        ("nan", "nan is not a finite number"),
        ("-inf", "-inf is not a finite number"),
        ("1e300", "1e+300 is beyond float32's range"),
        ("1" + "0" * 45, "1000000000000000000000000000000000000000000000 is beyond float32"),
    ]:
        with pytest.raises(InputError) as caught:
            parse_scene(base + f"albedo = [0.5, {value}, 0.5]\n", "s.toml")
        assert caught.value.message.startswith(f"s.toml: materials.m.albedo[1]: {expected}")


def test_negative_zero_is_zero() -> None:
    scene = scene_from_dict(_with_sphere(position=[-0.0, 0.0, -0.0]))
    assert [math.copysign(1.0, x) for x in scene.objects[0].position] == [1.0, 1.0, 1.0]
    assert (
        glint.compose(_with_sphere(position=[-0.0, 0.0, 0.0])).text
        == glint.compose(_with_sphere(position=[0.0, 0.0, 0.0])).text
    )


# --- directions: normalisable in float32 --------------------------------------------------------


@pytest.mark.parametrize(
    ("data", "expected"),
    [
        (
            base_scene(objects=[{"shape": "plane", "material": "m", "normal": [1e-30, 0.0, 0.0]}]),
            "objects[0]: normal [1e-30, 0.0, 0.0] cannot be normalised in float32",
        ),
        (
            base_scene(objects=[{"shape": "plane", "material": "m", "normal": [1e30, 1e30, 0.0]}]),
            "objects[0]: normal [1e+30, 1e+30, 0.0] cannot be normalised in float32",
        ),
        (
            base_scene(objects=[{"shape": "plane", "material": "m", "normal": [0.0, 0.0, 0.0]}]),
            "objects[0]: normal must not be the zero vector",
        ),
        (
            base_scene(lights=[{"type": "directional", "direction": [0.0, 1e-20, 0.0]}]),
            "lights[0]: direction [0.0, 1e-20, 0.0] cannot be normalised in float32",
        ),
        (
            base_scene(lights=[{"type": "back", "direction": [0.0, 0.0, 0.0]}]),
            "lights[0]: direction must not be the zero vector",
        ),
        (
            base_scene(lights=[{"type": "bounce", "direction": [1e25, 0.0, 0.0]}]),
            "lights[0]: direction [1e+25, 0.0, 0.0] cannot be normalised",
        ),
        (
            base_scene(camera={"type": "lookat", "position": [0.0, 0.0, 1e-20]}),
            "camera: position and target: the eye is 1e-20 from the target (along an axis), too",
        ),
        (
            base_scene(
                camera={
                    "type": "lookat",
                    "position": [1e8, 0.0, 0.0],
                    "target": [1e8 + 1.0, 0.0, 0.0],
                }
            ),
            "camera: position and target: the eye is 1 from the target, 1e+08 from the origin",
        ),
        (
            base_scene(camera={"type": "orbit", "radius": 1e-20, "height": 0.0}),
            "camera: radius and height: the eye is 1e-20 from the target (along an axis), too",
        ),
        (
            base_scene(camera={"type": "orbit", "radius": 1e25}),
            "camera: radius and height: the eye is 1e+25 from the target (along an axis), too far",
        ),
    ],
    ids=lambda v: v if isinstance(v, str) else "",
)
def test_a_direction_float32_cannot_normalise_is_refused(
    data: dict[str, Any], expected: str
) -> None:
    assert error(data).startswith(f"scene.toml: {expected}")


def test_a_small_but_normalisable_plane_normal_gives_the_unit_normal() -> None:
    tiny = glint.compose(base_scene(objects=[
        {"shape": "plane", "material": "m", "normal": [0.0, 1e-12, 0.0], "offset": 1e-12}
    ])).text  # fmt: skip
    unit = glint.compose(base_scene(objects=[
        {"shape": "plane", "material": "m", "normal": [0.0, 1.0, 0.0], "offset": 1.0}
    ])).text  # fmt: skip
    assert tiny == unit


# --- nesting ------------------------------------------------------------------------------------


def _nested(depth: int, placed: bool = True) -> dict[str, Any]:
    """A sphere under `depth` groups, every level placed (a point per level in the code, a box
    per level in the bounds), alternately unions, subtractions and repeats."""
    part: dict[str, Any] = {"shape": "sphere", "radius": 0.5}
    for level in range(depth):
        kind = ("union", "subtraction", "repeat")[level % 3]
        group: dict[str, Any] = {"shape": kind, "children": [part]}
        if kind == "repeat":
            group |= {"count": [2, 1, 1], "spacing": [0.01, 0.0, 0.0]}
        if placed:
            group |= {"position": [0.001, 0.0, 0.0], "rotation": [0.0, 0.5, 0.0]}
        part = group
    return part


def _run_with_little_stack(function: Any, frames: int = 250) -> Any:
    """function() called under `frames` extra Python frames: a caller that is itself deep."""
    if frames == 0:
        return function()
    return _run_with_little_stack(function, frames - 1)


def test_groups_nest_to_the_stated_depth_and_every_walk_survives_it() -> None:
    data = base_scene(objects=[{**_nested(MAX_GROUP_DEPTH), "material": "m"}])
    scene = _run_with_little_stack(lambda: scene_from_dict(data))
    shader = _run_with_little_stack(lambda: glint.compose(scene))
    assert f"q{MAX_GROUP_DEPTH}" in shader.text  # one placed point per level
    dumped = _run_with_little_stack(scene.model_dump)
    assert scene_from_dict(dumped).objects == scene.objects
    assert scene.model_dump_json()
    assert shader.explain()
    assert glint.compose(data, target="webgl2").text  # another target: the same walks


def test_groups_nested_past_the_depth_name_the_key_and_the_limit() -> None:
    data = base_scene(objects=[{**_nested(MAX_GROUP_DEPTH + 1, placed=False), "material": "m"}])
    message = error(data)
    # the part one level too deep: 1 + 98 + 2 levels of children
    assert message.startswith(
        "scene.toml: objects[0].children[0]…(98 more levels)….children[0].children[0]: "
        f"groups nest at most {MAX_GROUP_DEPTH} levels deep"
    )
    for depth in (300, 5000):  # past pydantic's own limit, and past Python's recursion limit
        data = base_scene(objects=[{**_nested(depth, placed=False), "material": "m"}])
        assert f"groups nest at most {MAX_GROUP_DEPTH} levels deep" in error(data)


def test_deeply_nested_toml_arrays_and_tables_are_one_message() -> None:
    for text in ("a = " + "[" * 5000 + "]" * 5000, "a = " + "{b = " * 5000 + "1" + "}" * 5000):
        with pytest.raises(InputError) as caught:
            parse_scene(text, "deep.toml")
        assert caught.value.message.startswith("deep.toml: ")
    with pytest.raises(InputError, match="nested more than"):
        parse_scene("a = " + "[" * 400 + "]" * 400, "deep.toml")


def test_deep_groups_in_a_toml_file_are_refused_by_the_cli(tmp_path: Path) -> None:
    lines = ["[[objects]]", 'shape = "union"', 'material = "m"']
    key = "objects"
    for level in range(MAX_GROUP_DEPTH + 50):
        key += ".children"
        lines += [f"[[{key}]]", 'shape = "union"' if level < MAX_GROUP_DEPTH + 49 else
                  'shape = "sphere"']  # fmt: skip
    lines += ["[materials.m]", "albedo = [1.0, 1.0, 1.0]"]
    scene = tmp_path / "deep.toml"
    scene.write_text("\n".join(lines) + "\n")
    done = subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", "compose", str(scene)],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 1, done.stderr
    assert f"groups nest at most {MAX_GROUP_DEPTH} levels deep" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_box_of_bounds_past_float32_is_left_out_for_the_whole_ray() -> None:
    from glint.compiler.compose.codegen.bounds import span_unit

    scene = scene_from_dict(base_scene(objects=[
        {"shape": "box", "material": "m", "size": [1e20, 1.0, 1.0], "scale": 1e30}
    ]))  # fmt: skip
    body = span_unit(scene.objects, False).body
    assert "return vec2(0.0, 1e30);" in body and "e+50" not in body


def test_the_readme_example_message_is_what_glint_says() -> None:
    readme = (ROOT / "README.md").read_text()
    found = re.search(r"Each of these is one message with the key, e\.g\. `(.*?)`", readme, re.S)
    assert found is not None
    quoted = " ".join(found.group(1).split())
    data = base_scene(objects=[
        {"shape": "sphere", "material": "m"},
        {"shape": "plane", "material": "m", "normal": [1e-300, 1.0, 0.0]},
    ])  # fmt: skip
    assert error(data) == quoted


def test_geometry_material_ids_are_glsl_ints() -> None:
    for key in ("1" * 30, "x", "٣", "2147483648", "-"):
        data = base_scene(geometry={"file": "g.glsl", "materials": {key: "m"}})
        assert "geometry: materials: key " in error(data)
        assert "is not an integer id (a GLSL int" in error(data)


@pytest.mark.parametrize(
    ("data", "key"),
    [
        (
            base_scene(
                lights=[{"type": "directional", "direction": [1.0, 1.0, 1.0], "intensity": 3e38}]
            ),
            "lights[0].intensity",
        ),  # fmt: skip
        (base_scene(lights=[{"type": "sky", "color": [1e7, 1.0, 1.0]}]), "lights[0].color[0]"),
    ],
)
def test_a_light_whose_radiance_would_overflow_shading_is_refused(
    data: dict[str, Any], key: str
) -> None:
    """Each of these is a finite float32, but shading multiplies colour by intensity and by the
    specular peak: past 1e6 the product reaches inf and the picture goes black with exit 0."""
    message = error(data)
    assert message.startswith(f"scene.toml: {key}: input should be less than or equal to 1000000")


@pytest.mark.render
def test_the_brightest_light_allowed_still_renders_finite_pixels() -> None:
    """At the bound (colour and intensity both 1e6), every pixel is finite under each tone map."""
    for tonemap in ("reinhard", "aces", "none"):
        light = {"type": "directional", "direction": [1.0, 1.0, 1.0], "color": [1e6] * 3,
                 "intensity": 1e6}  # fmt: skip
        scene = base_scene(lights=[light], post={"tonemap": tonemap})
        stats = glint.render(glint.compose(scene), size=(48, 27)).stats
        assert stats["nan"] == 0 and stats["inf"] == 0, (tonemap, stats)
