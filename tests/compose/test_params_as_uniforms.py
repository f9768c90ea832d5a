"""`glint compose --target webgl2 --params-as-uniforms`: ranged parameters become uniforms with
a manifest for the page's sliders; constant-expression uses stay #defines; nothing else moves."""

from __future__ import annotations

import re
import shutil
from collections.abc import Callable, Collection
from pathlib import Path

import pytest
from mesh_scenes import example_params

from glint import compose
from glint.compiler.cli import main
from glint.compiler.compose.linking.uniform_params import constant_uses, read_manifest
from glint.compiler.target.glslang import validate

SCENES = example_params("its programs take their parameters as #defines only (no webgl2 target)")
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)


def _uniform_names(text: str) -> list[str]:
    return re.findall(r"^uniform (?:float|int|vec3) ([A-Z_][A-Z0-9_]*);$", text, re.M)


def test_ranged_parameters_become_uniforms_listed_in_the_manifest() -> None:
    # the reference tier marches (the others trace the default scene in closed form)
    shader = compose(target="webgl2", params_as_uniforms=True, tier="reference")
    manifest = read_manifest(shader.text)
    assert manifest == list(shader.uniforms)
    assert [p.name for p in manifest] == _uniform_names(shader.text)
    by_name = {p.name: p for p in manifest}
    # the default scene's AO and march step count (an int: a loop bound, fine in ES 3.00)
    ao = by_name["AO_STRENGTH"]
    assert (ao.type, ao.default, ao.min, ao.max) == ("float", 3.0, 0.0, 10.0)
    assert by_name["MARCH_STEPS"].type == "int"
    assert isinstance(by_name["MARCH_STEPS"].default, int)
    for param in manifest:
        assert f"#define {param.name} " not in shader.text
        values = param.default if isinstance(param.default, list) else [param.default]
        assert all(param.min <= value <= param.max for value in values)
    # parameters with no range stay #defines (a slider needs bounds)
    assert "#define CAMERA_HEIGHT 1.5" in shader.text


def test_only_the_parameter_block_differs_from_the_plain_webgl2_shader() -> None:
    plain = compose(target="webgl2").text
    shader = compose(target="webgl2", params_as_uniforms=True)
    names = {p.name for p in shader.uniforms}
    kept = [
        line
        for line in shader.text.splitlines()
        if not any(line == f"uniform {p.type} {p.name};" for p in shader.uniforms)
    ]
    start = kept.index("/* glint-params")
    del kept[start : start + 3]
    expected = [
        line
        for line in plain.splitlines()
        if not (line.startswith("#define ") and line.split()[1] in names)
    ]
    assert kept == expected
    assert "glint-params" not in plain


@pytest.mark.parametrize("scene", SCENES)
@needs_glslang
def test_every_example_scene_validates_with_uniforms(scene: Path) -> None:
    shader = compose(scene, target="webgl2", params_as_uniforms=True)
    assert shader.uniforms
    assert validate(shader.text, scene.name, "webgl2") == []


SOURCE = """#version 300 es
precision highp float;
DECLARATIONS
#define TWICE_C (C * 2.0)
#define USES_H H
const float k = A * 2.0;
float g = TWICE_C;
float arr[D + 1];
#if USES_H > 1
#endif
out vec4 o;
void main() {
    float v = B;
    for (int i = 0; i < E; i++) { v += F; }
    switch (E) { case 1: break; }
    const float local = G;
    o = vec4(v + local + k + g + arr[0]);
}
"""


INTS = ("D", "E", "H")


def _shader_with(source: str) -> Callable[[Collection[str]], str]:
    """`source` with the given names declared as uniforms and the others #defined."""

    def shader_with(uniforms: Collection[str]) -> str:
        lines = []
        for name in "ABCDEFGH":
            kind = "int" if name in INTS else "float"
            value = "2" if name in INTS else "2.0"
            lines.append(
                f"uniform {kind} {name};" if name in uniforms else f"#define {name} {value}"
            )
        return source.replace("DECLARATIONS", "\n".join(lines))

    return shader_with


def test_constant_expression_uses_are_found_by_the_parser() -> None:
    found = constant_uses("ABCDEFGH", _shader_with(SOURCE))
    # const initialisers (global and local), a global's initialiser through a macro, an array
    # size, a #if through a macro; not B, E (a loop bound, a switch selector) or F
    assert found == {"A", "C", "D", "G", "H"}


def test_case_labels_need_constants() -> None:
    source = SOURCE.replace("case 1:", "case int(B):")
    assert "B" in constant_uses(["B"], _shader_with(source))


def test_other_targets_are_refused_with_one_message(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["compose", "--params-as-uniforms"]) == 2
    err = capsys.readouterr().err
    assert err.strip() == "glint: --params-as-uniforms needs --target webgl2, not shadertoy"


@needs_glslang
def test_cli_writes_a_shader_that_validates(tmp_path: Path) -> None:
    out = tmp_path / "live.glsl"
    assert main(["compose", "--target", "webgl2", "--params-as-uniforms", "-o", str(out)]) == 0
    assert read_manifest(out.read_text())
    assert main(["validate", "--target", "webgl2", str(out)]) == 0


def test_the_scenes_lights_materials_and_exposure_are_knobs_too() -> None:
    """Issue 27: a page sets a light's intensity and direction, a material's albedo, roughness
    and metallic, the dielectric F0 and the exposure live; ShaderToy code names the same values
    as #defines a reader can change."""
    scene = Path(__file__).resolve().parents[2] / "snippets" / "scenes" / "metal_spheres.toml"
    shader = compose(scene, target="webgl2", params_as_uniforms=True)
    by_name = {p.name: p for p in read_manifest(shader.text)}
    copper = by_name["MAT_COPPER_ROUGHNESS"]
    assert (copper.default, copper.min, copper.max) == (0.3, 0.0, 1.0)
    assert by_name["MAT_COPPER_METALLIC"].default == 1.0
    assert "MAT_PLASTIC_METALLIC" not in by_name  # a dielectric has no metallic path to turn
    sun = by_name["SUN_INTENSITY"]
    assert sun.default == 3.0 and sun.min > 0 and sun.max / sun.min >= 100  # a log slider
    assert by_name["EXPOSURE"].default == 1.0
    albedo = by_name["MAT_COPPER_ALBEDO"]
    assert (albedo.type, albedo.control, albedo.default) == ("vec3", "color", [0.95, 0.64, 0.54])
    direction = by_name["SUN_DIR"]
    assert (direction.type, direction.control) == ("vec3", "direction")
    assert abs(sum(c * c for c in direction.default) - 1.0) < 1e-5  # a unit vector
    f0 = by_name["DIELECTRIC_F0"]
    assert (f0.default, f0.min) == (0.04, 0.0) and f0.max >= 0.17  # up to diamond's
    toy = compose(scene).text
    assert "#define SUN_INTENSITY 3.0" in toy and "#define EXPOSURE 1.0" in toy
    assert "#define MAT_COPPER_ALBEDO vec3(0.95, 0.64, 0.54)" in toy
    assert "makeSurface(P, N, V, MAT_COPPER_ALBEDO, MAT_COPPER_ROUGHNESS)" in toy
    assert "#define SUN_DIR normalize(vec3(" in toy and "#define DIELECTRIC_F0 0.04" in toy


@pytest.mark.render
def test_post_exposure_scales_the_light_before_the_tone_map(tmp_path: Path) -> None:
    import glint

    text = (
        Path(__file__).resolve().parents[2] / "snippets" / "scenes" / "default.toml"
    ).read_text()
    brighter = tmp_path / "brighter.toml"
    brighter.write_text(text.replace("[post]\n", "[post]\nexposure = 2.0\n"))
    assert "exposure = 2.0" in brighter.read_text()
    plain = glint.render(glint.compose(None), size=(64, 36), time=1.0).pixels
    lit = glint.render(glint.compose(brighter), size=(64, 36), time=1.0).pixels
    assert lit.mean() > plain.mean() + 0.05
