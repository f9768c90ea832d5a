"""glslangValidator runs on the ShaderToy-wrapped code and reports at the user's file and line."""

from __future__ import annotations

import shutil

import pytest

from glint.compiler.errors import EnvironmentProblem, UsageError
from glint.compiler.glslang import find_validator, spirv_instruction_count, validate
from glint.compiler.sourcemap import Origin, build_line_map

needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)

VALID = """\
float brightness(vec2 uv) {
    return 0.5 + 0.5 * sin(iTime + uv.x);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = vec4(vec3(brightness(uv)), 1.0) + texture(iChannel0, uv) * iMouse.x;
}
"""


def test_line_map_follows_markers() -> None:
    text = (
        "// header\n"
        "// source: snippets/D/ggx.glsl:12\n"
        "float D_GGX() {\n"
        "    return 1.0;\n"
        "// source: <generated>:1\n"
        "void mainImage() {}\n"
    )
    assert build_line_map(text, "out.glsl") == [
        Origin("out.glsl", 1),
        Origin("out.glsl", 2),
        Origin("snippets/D/ggx.glsl", 12),
        Origin("snippets/D/ggx.glsl", 13),
        Origin("out.glsl", 5),
        Origin("out.glsl", 6),
    ]


def test_marker_must_be_a_whole_line() -> None:
    origins = build_line_map("  // source: a.glsl:3\nx\n", "out.glsl")
    assert origins == [Origin("out.glsl", 1), Origin("out.glsl", 2)]


@needs_glslang
@pytest.mark.parametrize("target", ["shadertoy", "webgl2", "desktop"])
def test_valid_shader_has_no_diagnostics(target: str) -> None:
    assert validate(VALID, "ok.glsl", target) == []


@needs_glslang
@pytest.mark.parametrize("target", ["shadertoy", "desktop"])
def test_error_is_reported_at_the_user_line_and_token(target: str) -> None:
    source = VALID.replace("vec2 uv = fragCoord", "vec2 uv = fragCoordd")
    [diagnostic] = validate(source, "bad.glsl", target)
    assert (diagnostic.file, diagnostic.line, diagnostic.severity) == ("bad.glsl", 6, "error")
    assert diagnostic.column == source.splitlines()[5].index("fragCoordd") + 1
    assert "fragCoordd" in diagnostic.message
    assert str(diagnostic).startswith(f"bad.glsl:6:{diagnostic.column}: error: ")


@needs_glslang
def test_syntax_error_column_points_at_the_unexpected_token() -> None:
    source = "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(1.0)\n}\n"
    [diagnostic] = validate(source, "s.glsl")
    assert (diagnostic.line, diagnostic.column) == (3, 1)
    assert "syntax error" in diagnostic.message


@needs_glslang
def test_error_in_composed_shader_maps_to_the_snippet() -> None:
    composed = (
        "// glint: composed shader\n"
        "// source: snippets/D/ggx.glsl:7\n"
        "float D_GGX(float NoH, float a) {\n"
        "    float a2 = a * a;\n"
        "    return a2 / (NoH * undefinedThing);\n"
        "}\n"
        "// source: <generated>:1\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    fragColor = vec4(D_GGX(0.5, 0.3));\n"
        "}\n"
    )
    [diagnostic] = validate(composed, "scene.glsl")
    assert (diagnostic.file, diagnostic.line) == ("snippets/D/ggx.glsl", 9)
    assert diagnostic.column == composed.splitlines()[4].index("undefinedThing") + 1


@needs_glslang
def test_missing_main_image_is_explained() -> None:
    [diagnostic] = validate("float helper() { return 1.0; }\n", "m.glsl")
    assert (diagnostic.file, diagnostic.line) == ("m.glsl", 1)
    assert "mainImage is not defined" in diagnostic.message
    assert "void mainImage(out vec4 fragColor, in vec2 fragCoord)" in diagnostic.message


@needs_glslang
def test_wrong_main_image_signature_is_explained() -> None:
    [diagnostic] = validate("void mainImage(out vec4 c) {\n    c = vec4(1.0);\n}\n", "m.glsl")
    assert (diagnostic.line, diagnostic.column) == (1, 6)  # at the user's definition
    assert "wrong signature" in diagnostic.message


@needs_glslang
def test_user_main_is_reported_where_it_is_defined() -> None:
    source = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n\nvoid main() {}\n"
    [diagnostic] = validate(source, "m.glsl")
    assert (diagnostic.line, diagnostic.column) == (3, 6)
    assert "do not define `main`" in diagnostic.message


def test_unknown_target_is_a_usage_error() -> None:
    with pytest.raises(UsageError, match="desktop"):
        validate(VALID, target="vulkan")


def test_missing_validator_is_an_environment_problem(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PATH", "")
    with pytest.raises(EnvironmentProblem, match="glslang-tools") as raised:
        find_validator()
    assert raised.value.exit_code == 2
    with pytest.raises(EnvironmentProblem):
        validate(VALID)


@needs_glslang
@pytest.mark.skipif(shutil.which("spirv-dis") is None, reason="spirv-dis is not installed")
def test_spirv_instruction_count_grows_with_code() -> None:
    small = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n"
    count = spirv_instruction_count(VALID)
    assert count is not None and count > spirv_instruction_count(small)  # type: ignore[operator]
    assert spirv_instruction_count("not glsl") is None
