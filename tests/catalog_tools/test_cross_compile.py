"""HLSL and MSL through SPIR-V: every catalog snippet (`catalog show ID --lang hlsl`) and the
default scene at each tier (`compose --target hlsl`) compile back with glslang's HLSL front end;
the snippet's functions keep their names and parameter counts; the MSL has a fragment function;
a broken shader and a missing spirv-cross are one clear line each. Real glslangValidator and
spirv-cross, nothing mocked."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import glint
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.catalog.tiers import TIERS
from glint.compiler.catalog_tools.cross import show_in
from glint.compiler.errors import InputError
from glint.compiler.glsl.symbols import analyze
from glint.compiler.target.cross import check_hlsl, cross_compile_image
from glint.compiler.target.shadertoy import UNIFORM_NAMES

GLINT = [sys.executable, "-m", "glint.compiler.cli"]
CATALOG = load_catalog()
# A term, a lobe with slot dependencies, scene-querying snippets, the camera (uses iTime).
MSL_SHOWN = ["D.ggx", "specular.cook_torrance", "shadow.soft", "camera.orbit"]

pytestmark = pytest.mark.skipif(
    shutil.which("spirv-cross") is None or shutil.which("glslangValidator") is None,
    reason="needs spirv-cross and glslangValidator: run `make setup`",
)


def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*GLINT, *args], capture_output=True, text=True, timeout=120, env=env)


@pytest.fixture(scope="module")
def hlsl_of() -> dict[str, str]:
    """Every snippet's `catalog show --lang hlsl`, converted once for the tests below."""
    return {snippet_id: show_in(snippet_id, "hlsl", CATALOG) for snippet_id in CATALOG.snippets}


def hlsl_functions(hlsl: str) -> dict[str, int]:
    """Each function SPIRV-Cross defines at the top level: its name and parameter count."""
    found = re.findall(r"^[A-Za-z_][\w<>]*\s+([A-Za-z_]\w*)\(([^)]*)\)\s*$", hlsl, re.M)
    return {name: len([p for p in params.split(",") if p.strip()]) for name, params in found}


def test_every_snippet_compiles_back_from_hlsl(hlsl_of: dict[str, str]) -> None:
    errors = {snippet_id: check_hlsl(hlsl) for snippet_id, hlsl in hlsl_of.items()}
    assert not {snippet_id: found[:2] for snippet_id, found in errors.items() if found}
    assert len(hlsl_of) == len(CATALOG.snippets) > 90


def provided_functions(snippet_id: str) -> dict[str, int]:
    """The functions a snippet provides (not its #defines) and their parameter counts."""
    snippet = CATALOG.get(snippet_id)
    glsl = analyze(snippet.body, snippet.relpath, provided=UNIFORM_NAMES).functions
    return {f.name: len(f.params) for f in glsl if f.name in snippet.provides}


def test_every_snippet_keeps_its_function_names_and_arities(hlsl_of: dict[str, str]) -> None:
    checked = 0
    for snippet_id, hlsl in hlsl_of.items():
        wanted = provided_functions(snippet_id)
        checked += bool(wanted)  # core.constants provides only #defines
        converted = hlsl_functions(hlsl)
        for name, count in wanted.items():
            assert converted.get(name) == count, (snippet_id, name, count, converted)
    assert checked >= len(hlsl_of) - 2


def hlsl_writable(hlsl: str) -> set[tuple[str, int]]:
    """(function, parameter index) of each `out` or `inout` parameter SPIRV-Cross declares."""
    found = set()
    for name, params in re.findall(
        r"^[A-Za-z_][\w<>]*\s+([A-Za-z_]\w*)\(([^)]*)\)\s*$", hlsl, re.M
    ):
        for index, param in enumerate(params.split(",")):
            if {"out", "inout"} & set(param.split()):
                found.add((name, index))
    return found


def test_an_in_parameter_stays_in(hlsl_of: dict[str, str]) -> None:
    """SPIRV-Cross writes a parameter the function assigns to as `inout`, which in HLSL writes
    back to the caller's variable: a snippet must not assign to its `in` parameters."""
    checked = 0
    for snippet_id, hlsl in hlsl_of.items():
        snippet = CATALOG.get(snippet_id)
        functions = analyze(snippet.body, snippet.relpath, provided=UNIFORM_NAMES).functions
        for function in functions:
            if function.name not in snippet.provides:
                continue
            for index, param in enumerate(function.params):
                if (function.name, index) in hlsl_writable(hlsl):
                    assert {"out", "inout"} & set(param.qualifier.split()), (
                        f"{snippet_id}: {function.name} assigns to its in parameter {param.name}"
                    )
                checked += 1
    assert checked > 150


def test_ggx_reads_like_its_glsl(hlsl_of: dict[str, str]) -> None:
    hlsl = hlsl_of["D.ggx"]
    assert re.search(r"^float distribution\(\w* ?float NoH, float a\)$", hlsl, re.M)
    # the #define parameters are named constants, not bare numbers
    assert "static const float PI = " in hlsl
    assert "static const float MIN_GGX_DENOM = " in hlsl
    assert "MIN_GGX_DENOM)" in hlsl
    assert hlsl.startswith("// glint catalog show D.ggx --lang hlsl: GGX")


def test_the_readme_unity_example_compiles(hlsl_of: dict[str, str]) -> None:
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    example = re.search(r"```hlsl\n(.*?)```", readme, re.S)
    assert example is not None
    body = example.group(1).split('#include "ggx.hlsl"\n', 1)[1].split("ENDHLSL")[0]
    frag = (
        "float _Roughness;\n"
        "float4 frag(float4 pos : SV_Position, float3 N : NORMAL, float3 V : TEXCOORD0,\n"
        "            float3 L : TEXCOORD1) : SV_Target {\n"
        f"{body}    return float4(D, D, D, 1.0);\n}}\n"
    )
    assert check_hlsl(hlsl_of["D.ggx"] + frag, entry="frag") == []


def test_scene_functions_get_stand_ins(hlsl_of: dict[str, str]) -> None:
    hlsl = hlsl_of["shadow.soft"]
    assert "map: stand-ins that return 0" in hlsl
    assert re.search(r"^float map\(float3 p\)$", hlsl, re.M)


@pytest.mark.parametrize("snippet_id", MSL_SHOWN)
def test_msl_has_a_fragment_function_and_the_snippet(snippet_id: str) -> None:
    msl = show_in(snippet_id, "msl", CATALOG)
    assert "#include <metal_stdlib>" in msl
    assert re.search(r"^fragment main0_out main0\(", msl, re.M)
    names = provided_functions(snippet_id)
    assert names
    for name in names:
        assert re.search(rf"^\w[\w:<>]* {name}\(", msl, re.M), name


@pytest.mark.parametrize("tier", TIERS)
def test_composed_scene_compiles_back_from_hlsl(tier: str) -> None:
    shader = glint.compose(target="hlsl", tier=tier)
    assert check_hlsl(shader.text) == []
    assert shader.text.startswith(f"// glint {glint.__version__} - scene 'default'")
    assert f"tier {tier}, target hlsl" in shader.text.splitlines()[0]
    assert re.search(r"^cbuffer ShaderToy : register\(b0\)$", shader.text, re.M)
    assert re.search(r"^\s+float3 iResolution : packoffset\(c0\);$", shader.text, re.M)
    assert ": SV_Position;" in shader.text
    assert re.search(
        r"^void mainImage\(out float4 fragColor, float2 fragCoord\)$", shader.text, re.M
    )
    # ShaderToy counts fragCoord from the bottom row, SV_Position from the top
    assert "iResolution.y - gl_FragCoord.y" in shader.text


def test_composed_scene_as_msl() -> None:
    shader = glint.compose(target="msl")
    assert re.search(r"^fragment main0_out main0\(constant ShaderToy& ", shader.text, re.M)
    assert "target msl" in shader.text.splitlines()[0]


def test_a_define_the_preprocessor_needs_stays_a_macro() -> None:
    # `#if` cannot read a constant: this one compiles only with SAMPLES left a macro
    source = (
        "#define SAMPLES 4\n#define GAIN 0.5\n"
        "#if SAMPLES > 2\nfloat gain() { return GAIN; }\n#endif\n"
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(gain() * float(SAMPLES)); }\n"
    )
    hlsl = cross_compile_image(source, "hlsl")
    assert check_hlsl(hlsl) == []
    assert re.search(r"^float gain\(\)$", hlsl, re.M)
    assert "static const float GAIN" not in hlsl  # the whole shader fell back to macros


def test_broken_glsl_is_one_clear_error_at_its_line() -> None:
    source = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(undefinedThing);\n}\n"
    with pytest.raises(InputError) as caught:
        cross_compile_image(source, "hlsl", "broken.glsl")
    assert "cannot convert to HLSL" in caught.value.message
    assert "broken.glsl:2:" in caught.value.message
    assert "undefinedThing" in caught.value.message


def test_broken_hlsl_is_caught_by_the_round_trip() -> None:
    errors = check_hlsl("float4 main() : SV_Target { return undefinedThing; }\n")
    assert errors and any("undefinedThing" in e for e in errors)


def test_cli_compose_and_catalog_show(tmp_path: Path) -> None:
    out = tmp_path / "scene.hlsl"
    composed = run("compose", "--target", "hlsl", "-o", str(out))
    assert composed.returncode == 0, composed.stderr
    assert check_hlsl(out.read_text()) == []
    shown = run("catalog", "show", "D.ggx", "--lang", "msl")
    assert shown.returncode == 0, shown.stderr
    assert "float distribution(" in shown.stdout and "fragment main0_out" in shown.stdout
    glsl = run("catalog", "show", "D.ggx")
    assert glsl.stdout == show_in("D.ggx", "glsl", CATALOG)
    refused = run("validate", str(out))
    assert refused.returncode == 2
    assert "takes GLSL" in refused.stderr and "Traceback" not in refused.stderr


def test_missing_spirv_cross_is_one_clear_line(tmp_path: Path) -> None:
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    validator = shutil.which("glslangValidator")
    assert validator
    os.symlink(validator, bin_dir / "glslangValidator")
    env = {**os.environ, "PATH": str(bin_dir)}
    for args in (["compose", "--target", "hlsl"], ["catalog", "show", "D.ggx", "--lang", "msl"]):
        result = run(*args, env=env)
        assert result.returncode == 2
        assert result.stdout == ""
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1, result.stderr
        assert "spirv-cross not found" in lines[0]
        assert "sudo apt-get install spirv-cross" in lines[0]
