"""ShaderToy's own world in `glint lint` and `glint validate`: HW_PERFORMANCE predefined, the
Common tab in front (`--common`, or NAME.common.glsl beside NAME.glsl), iChannelN typed by
`--channel N=2d|cube|3d`; glint's own `compose --split common` output clean. Real
glslangValidator, real files."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from glint.compiler.target.shadertoy import Tab
from glint.lint.options import Options
from glint.lint.runner import lint_source

pytestmark = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator needed"
)

ROOT = Path(__file__).resolve().parents[2]
MAIN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}\n}}\n"
# Uses HW_PERFORMANCE as ShaderToy shaders do; an undeclared name in the branch not taken
# shows which value the compilers saw.
HW = "#if HW_PERFORMANCE==0\n#define AA notTaken\n#else\n#define AA 2.0\n#endif\n" + MAIN.format(
    body="    fragColor = vec4(AA);"
)
COMMON = (
    "float fade(float t) {\n    return t * t;\n}\nconst float LO = 0.0;\nconst float HI = 1.0;\n"
)
IMAGE = MAIN.format(
    body="    float x = fade(fragCoord.x);\n    fragColor = vec4(clamp(x, HI, LO));"
)  # line 3: N008 (a default rule) sees the Common tab's constants


def glint(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", *args],
        capture_output=True, text=True, cwd=cwd, timeout=120,
    )  # fmt: skip


def lint_json(*args: str, cwd: Path) -> list[dict]:
    # the default rules and N008 (an opt-in rule), which sees the Common tab's constants
    select = [] if "--select" in args else ["--select", "DEFAULT,N008"]
    result = glint("lint", "--no-cache", "--format", "json", *select, *args, cwd=cwd)
    assert result.returncode in (0, 1), result.stderr
    return json.loads(result.stdout)


def codes(findings: list[dict]) -> list[tuple[str, int, str]]:
    return [(f["file"], f["line"], f["code"]) for f in findings]


# --- HW_PERFORMANCE ---------------------------------------------------------------------------


def test_hw_performance_is_predefined_as_on_a_desktop() -> None:
    assert lint_source(HW, "a.glsl") == []
    assert lint_source(HW, "a.glsl", Options(glslang=False)) == []  # glint's preprocessor too
    # not a ShaderToy page: nothing defines it there
    found = lint_source(HW, "a.glsl", Options(target="webgl2"))
    assert [(f.line, f.code) for f in found] == [(1, "C004")]  # glslang's C001 said the same


def test_a_shader_that_defines_hw_performance_keeps_its_own_value() -> None:
    # written for a runner without it: no redefinition error, and its own 0 is the one used
    own = "#define HW_PERFORMANCE 0\n" + HW
    found = lint_source(own, "a.glsl")
    assert [(f.code, f.line) for f in found] == [("C001", 8)]
    assert "notTaken" in found[0].message
    assert lint_source("#define HW_PERFORMANCE 1\n" + HW, "a.glsl") == []
    assert lint_source("#undef HW_PERFORMANCE\n#define HW_PERFORMANCE 1\n" + HW, "a.glsl") == []


# --- the Common tab ---------------------------------------------------------------------------


def test_a_common_tab_beside_the_file_is_put_in_front(tmp_path: Path) -> None:
    (tmp_path / "x.glsl").write_text(IMAGE)
    alone = lint_json("x.glsl", cwd=tmp_path)
    assert {f["code"] for f in alone} == {"C001"}  # fade, LO, HI: unknown without it
    (tmp_path / "x.common.glsl").write_text(COMMON)
    # glslang knows Common's functions, glint's rules its constants; the Common tab is linted
    # with the file that uses it, here clean
    assert codes(lint_json("x.glsl", cwd=tmp_path)) == [("x.glsl", 3, "N008")]
    validated = glint("validate", "x.glsl", cwd=tmp_path)
    assert validated.returncode == 0, validated.stdout + validated.stderr


def test_findings_in_the_common_tab_are_reported_once_on_its_file(tmp_path: Path) -> None:
    (tmp_path / "x.glsl").write_text(IMAGE)
    (tmp_path / "x.common.glsl").write_text(COMMON.replace("t * t", "t * undefinedT"))
    expected = [("x.common.glsl", 2, "C001"), ("x.glsl", 3, "N008")]
    for paths in (["x.glsl"], ["x.glsl", "x.common.glsl"], ["x.common.glsl", "x.glsl"], ["."]):
        found = lint_json(*paths, cwd=tmp_path)
        assert sorted(codes(found)) == expected, paths
    failed = glint("validate", "x.glsl", cwd=tmp_path)
    assert failed.returncode == 1 and failed.stdout.startswith("x.common.glsl:2:")


def test_common_given_by_flag_and_lines_of_the_file_stay_its_own(tmp_path: Path) -> None:
    (tmp_path / "lib.glsl").write_text(COMMON)
    (tmp_path / "a.glsl").write_text(IMAGE.replace("x = fade", "x = missing + fade"))
    found = lint_json("--common", "lib.glsl", "a.glsl", cwd=tmp_path)
    assert sorted(codes(found)) == [("a.glsl", 2, "C001"), ("a.glsl", 3, "N008")]
    assert glint("validate", "--common", "lib.glsl", "a.glsl", cwd=tmp_path).returncode == 1
    missing = glint("lint", "--common", "nope.glsl", "a.glsl", cwd=tmp_path)
    assert missing.returncode == 2 and "--common nope.glsl: no such file" in missing.stderr


def test_a_common_tab_alone_needs_no_main_image_and_has_no_pass_uniforms(tmp_path: Path) -> None:
    (tmp_path / "x.common.glsl").write_text(COMMON + "float now() { return iDate.w; }\n")
    assert lint_json("x.common.glsl", cwd=tmp_path) == []
    result = glint("validate", "x.common.glsl", cwd=tmp_path)
    assert result.returncode == 0 and "valid shadertoy Common tab" in result.stdout
    # ShaderToy compiles the Common tab with iDate and iSampleRate only
    (tmp_path / "x.common.glsl").write_text(COMMON + "float now() { return iTime; }\n")
    assert codes(lint_json("x.common.glsl", cwd=tmp_path)) == [("x.common.glsl", 6, "C001")]


def test_common_tab_content_is_part_of_the_cache_key(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "x.glsl").write_text(IMAGE)
    (tmp_path / "x.common.glsl").write_text(COMMON)
    first = glint("lint", "x.glsl", "--select", "DEFAULT,N008", "--format", "concise", cwd=tmp_path)
    assert first.stdout.startswith("x.glsl:3:")
    (tmp_path / "x.common.glsl").write_text(COMMON.replace("fade", "fadeOut"))
    second = glint(
        "lint", "x.glsl", "--select", "DEFAULT,N008", "--format", "concise", cwd=tmp_path
    )
    assert "'fade': no matching overloaded function" in second.stdout


# --- channels ---------------------------------------------------------------------------------

CUBE = MAIN.format(body="    fragColor = texture(iChannel0, vec3(fragCoord, 1.0));")
VOLUME = MAIN.format(body="    fragColor = vec4(vec3(textureSize(iChannel2, 0)), 1.0);")


def test_channels_are_typed_by_what_they_are_bound_to(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "c.glsl").write_text(CUBE)
    assert {f["code"] for f in lint_json("c.glsl", cwd=tmp_path)} == {"C001"}
    assert lint_json("c.glsl", "--channel", "0=cube", cwd=tmp_path) == []
    assert glint("lint", "c.glsl", "--channel", "0=cube", cwd=tmp_path).returncode == 0  # cached
    assert glint("lint", "c.glsl", cwd=tmp_path).returncode == 1  # not served the cube's entry
    assert glint("validate", "c.glsl", "--channel", "0=CUBE", cwd=tmp_path).returncode == 0
    (tmp_path / "pyproject.toml").write_text('[tool.glint.lint]\nchannels = { 0 = "cube" }\n')
    assert lint_json("c.glsl", cwd=tmp_path) == []
    # glint's own analysis types it too: textureSize of a sampler3D is an ivec3
    assert lint_source(VOLUME, "v.glsl", Options(channels=("2d", "2d", "3d", "2d"))) == []
    assert lint_source(VOLUME, "v.glsl") != []


@pytest.mark.parametrize("value", ["4=cube", "0=sphere", "cube", "0", "=2d"])
def test_a_bad_channel_is_one_usage_error(tmp_path: Path, value: str) -> None:
    for command in ("lint", "validate"):
        result = glint(command, "--channel", value, "c.glsl", cwd=tmp_path)
        assert result.returncode == 2 and result.stdout == ""
        [message] = [line for line in result.stderr.splitlines() if "error:" in line]
        assert "N=KIND" in message and "2d, cube, 3d" in message


def test_a_bad_channel_in_the_configuration_names_the_key(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.glint.lint]\nchannels = { 5 = "cube" }\n')
    result = glint("lint", "c.glsl", cwd=tmp_path)
    assert result.returncode == 2 and "tool.glint.lint.channels.5" in result.stderr


# --- glint's own split output -----------------------------------------------------------------


def test_compose_split_common_lints_and_validates_clean(tmp_path: Path) -> None:
    scene = ROOT / "snippets" / "scenes" / "default.toml"
    made = glint("compose", str(scene), "--split", "common", "-o", "scene.glsl", cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    assert (tmp_path / "scene.common.glsl").is_file()
    result = glint("lint", "--no-cache", "scene.glsl", "scene.common.glsl", cwd=tmp_path)
    assert result.returncode == 0 and "All clean" in result.stdout, result.stdout
    for tab in ("scene.glsl", "scene.common.glsl"):
        validated = glint("validate", tab, cwd=tmp_path)
        assert validated.returncode == 0, validated.stdout + validated.stderr


# --- the Python API ---------------------------------------------------------------------------


def test_lint_shader_takes_a_common_tab_and_channels(tmp_path: Path) -> None:
    import glint as api

    found = api.lint_shader(IMAGE, common=COMMON, select="DEFAULT,N008")
    assert [(f.file, f.line, f.code) for f in found] == [("<input>", 3, "N008")]
    (tmp_path / "lib.glsl").write_text(COMMON.replace("t * t", "t * undefinedT"))
    found = api.lint_shader(IMAGE, common=tmp_path / "lib.glsl", select="DEFAULT,N008")
    assert [(Path(f.file).name, f.code) for f in found] == [
        ("lib.glsl", "C001"),
        ("<input>", "N008"),
    ]
    assert api.lint_shader(CUBE, channels={0: "cube"}) == []
    for bad in ({4: "cube"}, {0: "sphere"}, {"0": "cube"}, ["0=cube"]):
        with pytest.raises(api.UsageError, match="channels"):
            api.lint_shader(CUBE, channels=bad)
    for wrong in (3, tmp_path / "nope.glsl"):
        with pytest.raises(api.UsageError, match="common"):
            api.lint_shader(CUBE, common=wrong)


def test_common_code_is_analysed_but_not_reported_with_the_file() -> None:
    common = "float f(float x) {\n    return clamp(x, 1.0, 0.0);\n}\n"
    image = MAIN.format(body="    fragColor = vec4(f(fragCoord.x));")
    options = Options(select=["DEFAULT", "N008"], glslang=False)
    assert lint_source(image, "x.glsl", options, tab=Tab(common=common, common_file="c")) == []
    alone = lint_source(common, "c", options, tab=Tab(is_common=True))
    assert [(f.line, f.code) for f in alone] == [(2, "N008")]
