"""Portability rules P001-P007: a positive and a negative case for each, their fixes, fixed
shaders that glslang accepts, idempotent fixing, and silence on the valid corpus."""

from __future__ import annotations

import inspect
import re
import shutil
import sys
from pathlib import Path

import pytest

from glint.lint.analysis.expression_types import expression_types
from glint.lint.analysis.model import semantic_model
from glint.lint.context import walk
from glint.lint.options import Options
from glint.lint.rules import REGISTRY, all_rules, rule_doc
from glint.lint.runner import build_context, lint_source, lint_text

FAST = Options(select=["P", "C1"], glslang=False)
CORPUS = sorted((Path(__file__).resolve().parent.parent / "corpus" / "valid").glob("*.glsl"))
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)
OUR_CODES = ["P001", "P002", "P003", "P004", "P005", "P006", "P007"]


def found(text: str, code: str | None = None) -> list[tuple[str, int, int]]:
    return [(f.code, f.line, f.column) for f in lint_source(text, "x.glsl", FAST)
            if code is None or f.code == code]  # fmt: skip


def fixed(text: str) -> str:
    return lint_text(text, "x.glsl", FAST, fix=True).text


def image(body: str, head: str = "") -> str:
    return f"{head}void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}\n}}\n"


# --- the registry ---------------------------------------------------------------------------


@pytest.mark.parametrize("code", OUR_CODES)
def test_rule_is_documented(code: str) -> None:
    rule = all_rules()[code]
    doc = rule_doc(rule)
    assert all(doc[k] for k in ("summary", "why", "example", "fix"))
    assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", rule.name)
    assert rule.category == "portability"
    assert REGISTRY[code] is rule


# --- P001 -----------------------------------------------------------------------------------


def test_p001_wrong_signature() -> None:
    src = "void mainImage(out vec3 color, vec2 uv) { color = vec3(uv, 0.0); }\n"
    assert found(src, "P001") == [("P001", 1, 6)]


def test_p001_wrong_parameter_count_and_near_miss_name() -> None:
    assert found("void mainImage(out vec4 c) { c = vec4(1.0); }\n", "P001")
    src = "void mainimage(out vec4 c, in vec2 p) { c = vec4(p, 0.0, 1.0); }\n"
    assert found(src, "P001") == [("P001", 1, 6)]


def test_p001_pixel_code_without_main_image() -> None:
    src = "vec4 shade() { return vec4(gl_FragCoord.xy, 0.0, 1.0); }\n"
    assert found(src, "P001") == [("P001", 1, 28)]


def test_p001_accepts_the_signature_with_or_without_in() -> None:
    assert not found("void mainImage(out vec4 c, vec2 p) { c = vec4(p, 0.0, 1.0); }\n")
    assert not found(image("fragColor = vec4(1.0);"))
    assert not found("void mainImage(out highp vec4 o, in highp vec2 u) { o = vec4(u, 0.0, 1.0); }")


def test_p001_leaves_libraries_and_complete_shaders_alone() -> None:
    assert not found("float sdSphere(vec3 p, float r) { return length(p) - r; }\n", "P001")
    complete = (
        "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n"
    )
    assert not found(complete, "P001")
    assert not found("void main() { }\n", "P001")


def test_p001_inout_colour_is_a_warning() -> None:
    findings = lint_source("void mainImage(inout vec4 c, in vec2 p) { c = vec4(1.0); }", "x", FAST)
    assert [(f.code, f.severity) for f in findings] == [("P001", "warning")]


# --- P002 -----------------------------------------------------------------------------------


def test_p002_fixes_gl_fragcolor_inside_main_image() -> None:
    src = image("    gl_FragColor = vec4(1.0);")
    assert found(src, "P002") == [("P002", 2, 5)]
    assert fixed(src) == image("    fragColor = vec4(1.0);")


def test_p002_gl_fragdata_zero() -> None:
    src = image("    gl_FragData[0] = vec4(1.0);")
    assert fixed(src) == image("    fragColor = vec4(1.0);")


def test_p002_no_fix_outside_main_image() -> None:
    src = "void paint() { gl_FragColor = vec4(1.0); }\n" + image("paint(); fragColor = vec4(1.0);")
    findings = lint_source(src, "x.glsl", FAST)
    assert [(f.code, f.fix) for f in findings] == [("P002", None)]


def test_p002_quiet_for_es1_and_es3_code() -> None:
    es1 = "#version 100\nprecision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n"
    assert not found(es1)
    assert not found(image("fragColor = vec4(1.0);"), "P002")


# --- P003 -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("old", "new", "args"),
    [
        ("texture2D", "texture", "iChannel0, fragCoord"),
        ("texture2DLod", "textureLod", "iChannel0, fragCoord, 0.0"),
        ("texture2DProj", "textureProj", "iChannel0, vec3(fragCoord, 1.0)"),
    ],
)
def test_p003_renames_es1_texture_functions(old: str, new: str, args: str) -> None:
    src = image(f"    fragColor = {old}({args});")
    assert found(src, "P003") == [("P003", 2, 17)]
    assert fixed(src) == image(f"    fragColor = {new}({args});")


def test_p003_texture_cube() -> None:
    src = "uniform samplerCube env;\n" + image("fragColor = textureCube(env, vec3(1.0));")
    assert "texture(env" in fixed(src)


def test_p003_leaves_a_shim_and_es3_names_alone() -> None:
    shim = "vec4 texture2D(sampler2D s, vec2 uv) { return texture(s, uv); }\n"
    assert not found(image("fragColor = texture2D(iChannel0, fragCoord);", shim), "P003")
    assert not found(image("fragColor = texture(iChannel0, fragCoord);"), "P003")


def test_p003_no_fix_on_a_line_with_a_macro() -> None:
    src = image("#define UV fragCoord\n    fragColor = texture2D(iChannel0, UV);")
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "P003"]
    assert len(findings) == 1 and findings[0].fix is None


# --- P004 -----------------------------------------------------------------------------------


def test_p004_renames_iglobaltime() -> None:
    src = image("    fragColor = vec4(sin(iGlobalTime));")
    assert found(src, "P004") == [("P004", 2, 26)]
    assert fixed(src) == image("    fragColor = vec4(sin(iTime));")


def test_p004_channel_resolution_needs_an_index() -> None:
    src = image("fragColor = vec4(fragCoord / iChannelResolution.xy, 0.0, 1.0);")
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "P004"]
    assert len(findings) == 1 and findings[0].fix is None


def test_p004_quiet_when_declared_or_modern() -> None:
    own = "uniform float iGlobalTime;\n"
    assert not found(image("fragColor = vec4(iGlobalTime);", own), "P004")
    body = "fragColor = vec4(iTime + iChannelResolution[0].x);"
    assert not found(image(body), "P004")


# --- P005 -----------------------------------------------------------------------------------

INT_FLOAT_CASES = [
    ("float x = 1;", "float x = 1.0;"),
    ("float x = -1;", "float x = -1.0;"),
    ("float x = fragCoord.x * 2;", "float x = fragCoord.x * 2.0;"),
    ("float x = pow(fragCoord.x, 2);", "float x = pow(fragCoord.x, 2.0);"),
    ("float x = max(fragCoord.x, 0);", "float x = max(fragCoord.x, 0.0);"),
    ("bool b = fragCoord.x > 0;", "bool b = fragCoord.x > 0.0;"),
    ("vec2 uv = fragCoord / 2;", "vec2 uv = fragCoord / 2.0;"),
    ("float x = fragCoord.x; x += 1;", "float x = fragCoord.x; x += 1.0;"),
    ("float x = fragCoord.x > 1.0 ? 1 : 0.5;", "float x = fragCoord.x > 1.0 ? 1.0 : 0.5;"),
    ("float x = fragCoord.x > 1.0 ? 1 : 0;", "float x = fragCoord.x > 1.0 ? 1.0 : 0.0;"),
    ("vec4 c = textureLod(iChannel0, fragCoord, 0);",
     "vec4 c = textureLod(iChannel0, fragCoord, 0.0);"),
    ("float a[2] = float[2](1, 2);", "float a[2] = float[2](1.0, 2.0);"),
    ("float x = smoothstep(0, 1, fragCoord.x);", "float x = smoothstep(0.0, 1.0, fragCoord.x);"),
]  # fmt: skip


@pytest.mark.parametrize(("before", "after"), INT_FLOAT_CASES)
def test_p005_fixes_int_literals(before: str, after: str) -> None:
    src = image(before + "\nfragColor = vec4(1.0);")
    assert found(src, "P005")
    assert fixed(src) == image(after + "\nfragColor = vec4(1.0);")


def test_p005_return_and_user_function_parameters() -> None:
    head = "float f(float v) { return 0; }\n"
    src = image("fragColor = vec4(f(1));", head)
    assert [c for c, *_ in found(src, "P005")] == ["P005", "P005"]
    assert fixed(src) == image("fragColor = vec4(f(1.0));", head.replace("0;", "0.0;"))


def test_p005_struct_constructor_members() -> None:
    head = "struct Hit { float d; int id; };\n"
    src = image("Hit h = Hit(1, 2);\nfragColor = vec4(h.d);", head)
    assert [(c, line, col) for c, line, col in found(src, "P005")] == [("P005", 3, 13)]
    assert fixed(src) == image("Hit h = Hit(1.0, 2);\nfragColor = vec4(h.d);", head)


def test_p005_int_variable_is_reported_without_a_fix() -> None:
    src = image("int i = 3;\nfloat x = fragCoord.x * i;\nfragColor = vec4(x);")
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "P005"]
    assert [(f.line, f.fix) for f in findings] == [(3, None)]
    assert "float(i)" in findings[0].message


@pytest.mark.parametrize(
    "code",
    [
        "vec3 v = vec3(1, 0, 0);",  # constructors convert
        "float x = float(3);",
        "int i = 2; int j = i * 2 + max(i, 0);",  # int arithmetic, int overloads
        "float a[3]; a[1] = 1.0; float x = a[1];",
        "vec4 t = texelFetch(iChannel0, ivec2(0), 0);",  # the level of texelFetch is an int
        "uint u = 1u; float x = float(u);",
        "float x = fragCoord.x; x *= float(2);",
        "ivec2 p = ivec2(fragCoord) / 2;",
        "float x = mix(0.0, 1.0, 0.5) * 2.0;",
    ],
)
def test_p005_leaves_valid_code_alone(code: str) -> None:
    assert not found(image(code + "\nfragColor = vec4(1.0);"), "P005")


def test_p005_respects_int_overloads_of_user_functions() -> None:
    head = "float f(float v) { return v; }\nfloat f(int v) { return float(v); }\n"
    assert not found(image("fragColor = vec4(f(1));", head), "P005")


def test_p005_hex_literal_has_no_fix() -> None:
    findings = [f for f in lint_source(image("float x = 0x10;\nfragColor = vec4(x);"), "x", FAST)
                if f.code == "P005"]  # fmt: skip
    assert len(findings) == 1 and findings[0].fix is None


# --- P006 -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("head", "what"),
    [
        ("float t = iTime * 0.5;\n", "the uniform `iTime`"),
        ("vec2 res = iResolution.xy;\n", "the uniform `iResolution`"),
        ("float a = 1.0;\nfloat b = a * 2.0;\n", "the non-const global `a`"),
        ("float f() { return 1.0; }\nfloat g = f();\n", "a call to `f`"),
        ("const float k = iTime;\n", "the uniform `iTime`"),
    ],
)
def test_p006_non_constant_global_initialiser(head: str, what: str) -> None:
    findings = [f for f in lint_source(image("fragColor = vec4(1.0);", head), "x", FAST)
                if f.code == "P006"]  # fmt: skip
    assert len(findings) == 1 and what in findings[0].message
    assert "mainImage" in findings[0].message


def test_p006_constant_initialisers_are_fine() -> None:
    head = (
        "const float PI = 3.14159;\nconst float TAU = 2.0 * PI;\nfloat s = sin(1.0) + TAU;\n"
        "vec3 up = vec3(0.0, 1.0, 0.0);\nconst vec3 k[2] = vec3[2](vec3(1.0), vec3(2.0));\n"
        "float later;\nuniform float gain;\n"
    )
    assert not found(image("later = iTime; fragColor = vec4(s + later + gain);", head), "P006")


# --- P007 -----------------------------------------------------------------------------------


def test_p007_reserved_words_even_when_the_file_does_not_parse() -> None:
    src = image("    float input = 1.0;\n    fragColor = vec4(input);")
    only = Options(select=["P", "C"], glslang=False)
    findings = lint_source(src, "x.glsl", only)
    assert [(f.code, f.line, f.column) for f in findings] == [("P007", 2, 11), ("P007", 3, 22)]


def test_p007_struct_members_and_functions() -> None:
    src = "struct S { float sample; };\nfloat filter(float x) { return x; }\n"
    assert [(c, line) for c, line, _ in found(src, "P007")] == [("P007", 1), ("P007", 2)]


def test_p007_not_in_comments_or_longer_names() -> None:
    src = image("// the input colour\nfloat inputs = 1.0; float sampled = inputs;\n"
                "fragColor = vec4(sampled);")  # fmt: skip
    assert not found(src, "P007")


def test_p007_through_a_macro_points_at_the_users_line() -> None:
    src = image("#define SCALE 2.0\n    float half = SCALE;\n    fragColor = vec4(1.0);")
    assert found(src, "P007") == [("P007", 3, 11)]


# --- fixing whole shaders -------------------------------------------------------------------

OLD_SHADER = """\
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    float x = 1;
    vec3 col = texture2D(iChannel0, uv).rgb * (0.5 + 0.5 * sin(iGlobalTime + uv.x * 2));
    fragColor = vec4(col * x, 1);
}
"""


@needs_glslang
def test_fixed_shader_validates_with_glslang() -> None:
    from glint.compiler.target.glslang import validate

    assert validate(OLD_SHADER, "x.glsl")  # broken as written
    result = lint_text(OLD_SHADER, "x.glsl", FAST, fix=True)
    assert result.fixed >= 4
    assert not [f for f in result.findings if f.code.startswith("P")]
    assert validate(result.text, "x.glsl") == []
    assert "texture(iChannel0" in result.text and "iTime" in result.text
    assert "float x = 1.0;" in result.text


def test_fixing_is_idempotent() -> None:
    once = lint_text(OLD_SHADER, "x.glsl", FAST, fix=True)
    twice = lint_text(once.text, "x.glsl", FAST, fix=True)
    assert twice.fixed == 0 and twice.text == once.text


def test_long_chains_do_not_recurse() -> None:
    # the shared analyses recurse over chains, so keep it short enough for them to build
    chain = " + ".join(["fragCoord.x"] * 150)
    src = image(f"float y = {chain} + 1;\nfragColor = vec4(texture2D(iChannel0, vec2(y)));")
    ctx = build_context(src, "x.glsl", FAST)
    assert ctx.tree is not None
    model, typed = semantic_model(ctx), expression_types(ctx)
    for node in reversed(list(walk(ctx.tree))):  # and warm their memos, children first
        model.type_of(node)
        typed.type_of(node)
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(len(inspect.stack()) + 100)  # less than the chain is deep
    try:
        codes = [f.code for code in OUR_CODES for f in all_rules()[code]().check(ctx)]
    finally:
        sys.setrecursionlimit(limit)
    assert sorted(codes) == ["P003", "P005"]


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_valid_corpus_has_no_portability_or_flow_findings(path: Path) -> None:
    assert found(path.read_text(encoding="utf-8")) == []
