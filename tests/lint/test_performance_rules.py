"""Performance rules PF001-PF003: a positive and a negative case for each, the fixes' text,
fixed shaders that glslang accepts, idempotent fixing, and silence on the valid corpora."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from glint.compiler.target.glslang import validate
from glint.lint.options import Options
from glint.lint.rules import all_rules, rule_doc
from glint.lint.runner import lint_source, lint_text

FAST = Options(select=["PF"], glslang=False)
CORPORA = Path(__file__).resolve().parent.parent / "corpus"
CORPUS = sorted((CORPORA / "valid").glob("*.glsl")) + sorted((CORPORA / "lint").glob("*.glsl"))
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)


def found(text: str, code: str | None = None) -> list[tuple[str, int, int]]:
    return [(f.code, f.line, f.column) for f in lint_source(text, "x.glsl", FAST)
            if code is None or f.code == code]  # fmt: skip


def fixed(text: str) -> str:
    return lint_text(text, "x.glsl", FAST, fix=True).text


def image(body: str, head: str = "") -> str:
    return f"{head}void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}\n}}\n"


@pytest.mark.parametrize("code", ["PF001", "PF002", "PF003", "PF004"])
def test_rule_is_documented(code: str) -> None:
    rule = all_rules()[code]
    doc = rule_doc(rule)
    assert all(doc[k] for k in ("summary", "why", "example", "fix"))
    assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", rule.name)
    assert rule.category == "performance" and rule.severity == "info"


# --- PF001 ----------------------------------------------------------------------------------

POWS = image(
    "    vec2 uv = fragCoord / iResolution.xy;\n"
    "    float t = uv.x;\n"
    "    float a = pow(t, 2.0);\n"
    "    float b = 1.0 / pow(uv.y, 3.0);\n"
    "    float c = pow(t, 4.0) + pow(t, 5.0);\n"
    "    vec3 d = pow(vec3(uv, t), vec3(2.0));\n"
    "    fragColor = vec4(d, a + b + c);"
)


def test_pf001_reports_small_integer_exponents_of_plain_values() -> None:
    assert [line for _, line, _ in found(POWS, "PF001")] == [4, 5, 6, 6]


def test_pf001_fix_writes_products_with_parentheses_where_precedence_needs_them() -> None:
    out = fixed(POWS)
    assert "float a = t * t;" in out
    assert "float b = 1.0 / (uv.y * uv.y * uv.y);" in out
    assert "float c = (t * t) * (t * t) + t * t * t * t * t;" in out
    assert fixed(out) == out  # idempotent
    assert found(out, "PF001") == []


def test_pf001_leaves_other_exponents_and_complex_bases_alone() -> None:
    src = image(
        "    float x = fragCoord.x;\n"
        "    float a = pow(x, 2.5) + pow(x, 8.0) + pow(x, x);\n"
        "    float b = pow(clamp(1.0 - x, 0.0, 1.0), 5.0) + pow(x + 1.0, 2.0);\n"
        "    fragColor = vec4(a + b);"
    )
    assert found(src, "PF001") == []


def test_pf001_leaves_compile_time_constant_bases_to_the_compiler() -> None:
    # a base built from literals, macros and const names, or a variable that still holds a
    # constant where it is read, is folded: no pow runs at all
    text = image(
        "    vec3 L = vec3(7.4, 5.6, 4.4);\n"
        "    L = pow(L, vec3(5.0)) * 2.0;\n"
        "    float r = 1.0 - clamp(SURF / RADIUS, 0., 1.);\n"
        "    float k = pow(r, 2.);\n"
        "    float c = pow(HALF, 3.0);\n"
        "    float t = fragCoord.x;\n"
        "    float v = pow(t, 2.0);\n"
        "    fragColor = vec4(L, k + c + v);",
        "#define SURF 0.01\n#define RADIUS 0.5\nconst float HALF = 0.5;\n",
    )
    assert found(text, "PF001") == [("PF001", 11, 15)]


def test_pf001_no_fix_on_a_line_with_a_macro() -> None:
    src = "#define E 2.0\n" + image("    float x = fragCoord.x;\n    fragColor = vec4(pow(x, E));")
    findings = lint_source(src, "x.glsl", FAST)
    assert [f.code for f in findings] == ["PF001"] and findings[0].fix is None


@needs_glslang
def test_pf001_fixed_shader_validates() -> None:
    out = fixed(POWS)
    assert out != POWS
    assert [d for d in validate(out, "x.glsl", "shadertoy") if d.severity == "error"] == []


# --- PF002 ----------------------------------------------------------------------------------

LOOP = """uniform vec3 lightPos;
float map(vec3 p) { return length(p) - 1.0; }
float shadow(vec3 ro, vec3 rd) {
    float res = 1.0;
    float t = 0.02;
    for (int i = 0; i < 64; i++) {
        float h = map(ro + rd * t);
        res = min(res, h / t * length(lightPos - ro));
        float wobble = sin(iTime) * 0.1;
        t += clamp(h, 0.02, 0.2) + wobble;
    }
    return res;
}
"""


def test_pf002_reports_loop_invariant_builtin_calls() -> None:
    assert found(LOOP, "PF002") == [("PF002", 8, 32), ("PF002", 9, 24)]
    message = lint_source(LOOP, "x.glsl", FAST)[0].message
    assert "length(lightPos - ro)" in message and "before the loop" in message


def test_pf002_ignores_varying_constant_and_user_function_work() -> None:
    src = """const vec3 kDir = vec3(0.0, 1.0, 0.0);
float map(vec3 p) { return length(p) - 1.0; }
float march(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < 64; i++) {
        float d = map(ro + rd * t);          // a user function: not judged
        float s = sin(float(i));             // the loop variable
        float c = cos(1.0) + length(kDir);   // constants: folded by the compiler
        vec3 p = ro + rd * t;
        float r = length(p);                 // declared in the loop
        t += d + s * 0.0 + c * 0.0 + r * 0.0;
    }
    return t;
}
"""
    assert found(src, "PF002") == []


def test_pf002_nested_loop_reports_once_at_the_outer_loop() -> None:
    src = """float f(vec3 a) {
    float s = 0.0;
    for (int i = 0; i < 8; i++) {
        for (int j = 0; j < 8; j++) {
            s += normalize(a).x;
        }
    }
    return s;
}
"""
    assert found(src, "PF002") == [("PF002", 5, 18)]


def test_pf002_only_hot_loops_count_and_nesting_goes_through_calls() -> None:
    src = """#define AA 3
#define R(p, a) p = cos(a) * p + sin(a) * vec2(p.y, -p.x)
float fold(vec3 p) {
    for (int i = 0; i < 6; i++) { p = abs(p) - vec3(1.0 + 0.2 * sin(iTime)); }
    return length(p);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 col = vec3(0.0);
    for (int m = 0; m < AA; m++)
        for (int n = 0; n < AA; n++)
            col += sin(iTime * vec3(1.0, 2.0, 3.0)) + vec3(float(m + n));
    float t = 0.0;
    vec2 q = fragCoord;
    for (int i = 0; i < 20; i++) { t += fold(vec3(q, t)); R(q, iTime * .1); }
    fragColor = vec4(col, t);
}
"""
    # the 3x3 AA grid runs 9 times: unrolled and merged; the fold runs 6 x 20 = 120 times
    # through its caller's loop, and R's rotation 20 times only
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "PF002"]
    assert [(f.line, f.column) for f in findings] == [(4, 48)]
    hot = src.replace("i < 20", "i < 99")
    messages = [f.message for f in lint_source(hot, "x.glsl", FAST) if f.code == "PF002"]
    assert any("(in the expansion of R)" in m for m in messages)


def test_pf002_variable_written_through_an_out_argument_varies() -> None:
    src = """void step_(inout vec3 p) { p += vec3(0.1); }
float f(vec3 p) {
    float s = 0.0;
    for (int i = 0; i < 4; i++) {
        s += length(p);
        step_(p);
    }
    return s;
}
"""
    assert found(src, "PF002") == []


# --- PF004 ----------------------------------------------------------------------------------


def test_pf004_reports_a_fetch_whose_coordinate_the_loop_does_not_change() -> None:
    src = image(
        "    vec2 uv = fragCoord / iResolution.xy;\n"
        "    vec3 col = vec3(0.0);\n"
        "    for (int i = 0; i < 4; i++) {\n"
        "        float r = texture(iChannel1, fragCoord / iChannelResolution[1].xy).x;\n"
        "        vec2 o = uv + vec2(float(i), r) * 0.01;\n"
        "        col += texture(iChannel0, o).rgb;\n"
        "    }\n"
        "    fragColor = vec4(col, 1.0);"
    )
    assert found(src, "PF004") == [("PF004", 5, 19)]
    message = lint_source(src, "x.glsl", FAST)[0].message
    assert "before the loop at line 4" in message and "fragCoord, iChannel1" in message


def test_pf004_a_fetch_that_depends_on_the_loop_through_variables_is_not_reported() -> None:
    src = image(
        "    vec2 uv = fragCoord / iResolution.xy;\n"
        "    vec3 p = vec3(uv, 0.0);\n"
        "    vec3 col = vec3(0.0);\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) {\n"
        "        float k = float(i) * 0.1;\n"
        "        vec2 c = uv + k;\n"
        "        col += texture(iChannel0, c).rgb;\n"  # through a local set from i
        "        col += texture(iChannel1, p.xy).rgb;\n"  # p is moved below
        "        vec2 s = uv;\n"
        "        if (t > 1.0) s = uv * 2.0;\n"  # written under a condition that varies
        "        col += texture(iChannel2, s).rgb;\n"
        "        p += vec3(0.1);\n"
        "        t += 0.1;\n"
        "    }\n"
        "    fragColor = vec4(col, 1.0);"
    )
    assert found(src, "PF004") == []


_MARCH = """
float map(vec3 p) { return length(p) - 1.0; }
vec3 floorColor(vec3 p) { return texture(iChannel1, vec2(0.5)).rgb; }
vec3 render(vec3 ro, vec3 rd) {
    float t = 0.0;
    vec3 acc = vec3(0.0);
    for (int i = 0; i < 100; i++) {
        float h = map(ro + rd * t);
        HIT
        t += h;
    }
    return acc;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 rd = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    fragColor = vec4(render(vec3(0.0, 0.0, -3.0), rd), 1.0);
}
"""


@pytest.mark.parametrize(
    "hit",
    [
        "if (h < 0.001) { vec3 c = texture(iChannel1, vec2(0.5)).rgb; return c; }",
        "if (h < 0.001) return texture(iChannel1, vec2(0.5)).rgb;",
        "if (h < 0.001) { acc = texture(iChannel1, vec2(0.5)).rgb; break; }",
        "if (h < 0.001) { acc = floorColor(ro + rd * t); break; }",  # a callee on that path
    ],
)
def test_pf004_work_on_the_path_that_leaves_the_loop_runs_once(hit: str) -> None:
    """A fetch (or a call that fetches) right before the march returns or breaks runs once per
    ray, not on every step: nothing to hoist. The same fetch on every step is reported."""
    assert found(_MARCH.replace("HIT", hit), "PF004") == []


@pytest.mark.parametrize(
    "hit",
    [
        "acc += texture(iChannel1, vec2(0.5)).rgb;",
        "acc += floorColor(ro + rd * t);",
        "if (h < 0.5) { acc += texture(iChannel1, vec2(0.5)).rgb; }",
    ],
)
def test_pf004_work_on_every_step_is_reported(hit: str) -> None:
    """The same fetch on every step of the march (or behind a condition that does not leave the
    loop, and a `break` of a switch, which leaves only the switch) is repeated: reported."""
    assert [f[0] for f in found(_MARCH.replace("HIT", hit), "PF004")] == ["PF004"]
    in_switch = "switch (i) { case 3: acc += texture(iChannel1, vec2(0.5)).rgb; break; }"
    assert [f[0] for f in found(_MARCH.replace("HIT", in_switch), "PF004")] == ["PF004"]


def test_pf004_a_short_loop_of_one_repeat_is_not_worth_a_finding() -> None:
    src = image(
        "    vec3 col = vec3(0.0);\n"
        "    for (int i = 0; i < 2; i++) {\n"
        "        col += texture(iChannel0, fragCoord / iResolution.xy).rgb * float(i);\n"
        "    }\n"
        "    fragColor = vec4(col, 1.0);"
    )
    assert found(src, "PF004") == []
    assert found(src.replace("i < 2", "i < 4"), "PF004") == [("PF004", 4, 16)]


def test_pf004_reports_invariant_work_of_a_function_the_march_calls() -> None:
    src = """float level;
float seed;
float bump(vec2 p) { return texture(iChannel1, p).x; }
float map(vec3 p) {
    float a = textureLod(iChannel3, vec2(0.5, 0.15), 0.0).x;
    float b = bump(p.xz);
    float c = texture(iChannel2, vec2(seed)).x;
    seed += 0.1;
    float d = texture(iChannel0, vec2(level)).x;
    return length(p) - 1.0 - a - b - c - d;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    level = iTime * 0.1;
    vec3 rd = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    float t = 0.0;
    for (int i = 0; i < 70; i++) t += map(rd * t);
    fragColor = vec4(t);
}
"""
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "PF004"]
    # a (constants) and d (a global set once in mainImage) are the same on every call; b reads
    # map's parameter; c reads a global that map itself moves
    assert [(f.line, f.column) for f in findings] == [(5, 15)]
    assert "1 more such at line 9" in findings[0].message
    assert "map, which runs up to 70 times per pixel from the loop at line 16" in (
        findings[0].message
    )


def test_pf004_reports_an_inner_march_that_reads_nothing_the_calls_change() -> None:
    src = """uniform float screenZ;
vec2 sceneMap(vec3 p) { return vec2(length(p) - 1.0, 0.0); }
float gizmo(vec3 p) {
    vec3 ray = normalize(vec3(iResolution.xy, screenZ));
    vec3 pos;
    float t = 0.01;
    for (int i = 0; i < 20; i++) {
        pos = ray * t;
        t += sceneMap(pos).x;
    }
    float e = 0.0;
    for (int j = 0; j < 20; j++) {
        e += sceneMap(p * e).x;
    }
    return length(p - pos) - 0.3 + e;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float t = 0.0;
    for (int i = 0; i < 60; i++) t += gizmo(vec3(fragCoord, t));
    fragColor = vec4(t);
}
"""
    assert found(src, "PF004") == [("PF004", 7, 5)]


def test_pf004_work_on_a_parameter_the_loop_passes_unchanged_is_the_same_on_every_call() -> None:
    src = """float map(vec3 p, vec2 uv) {
    float grain = texture(iChannel0, uv).x;
    return length(p) - 1.0 - 0.01 * grain;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 rd = normalize(vec3(uv - 0.5, 1.0));
    float t = 0.0;
    for (int i = 0; i < 80; i++) t += map(rd * t, uv);
    fragColor = vec4(t);
}
"""
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "PF004"]
    assert [(f.line, f.column) for f in findings] == [(2, 19)]
    assert "do not change between these calls" in findings[0].message
    # the same function called with a coordinate that moves along the ray
    assert found(src.replace("map(rd * t, uv)", "map(rd * t, uv * t)"), "PF004") == []


def test_pf004_an_inner_loop_that_breaks_on_a_changing_condition_varies() -> None:
    src = """float f(vec3 ro, vec3 rd, float limit) {
    float s = 0.0;
    for (int i = 0; i < 32; i++) {
        float t = 0.0;
        for (int j = 0; j < 16; j++) {
            if (s > limit) break;
            t += texture(iChannel0, ro.xy + rd.xy * t).x;
        }
        s += t;
    }
    return s;
}
"""
    assert found(src, "PF004") == []


def test_pf004_a_shadowed_counter_still_varies() -> None:
    src = """vec4 noise(float x) { return texture(iChannel0, vec2(x, 0.5)); }
float f(float seed) {
    float s = 0.0;
    for (float i = 0.0; i < 20.0; i++) {
        vec4 n = noise(seed + i);
        for (int i = 0; i < 3; i++) s += n.x * float(i);
    }
    return s;
}
"""
    assert found(src, "PF004") == []


def test_pf004_reports_a_loop_whose_body_ignores_its_counter() -> None:
    src = """vec2 hash22(vec2 p) { return fract(sin(vec2(dot(p, vec2(12.1, 7.3)), p.x)) * 4375.5); }
float cracks(vec2 p, float t) {
    float d = 1.0e10;
    for (float i = 0.; i < 25.; i++) {
        vec2 tp = hash22(p) - .5;
        tp *= max(0., (length(tp) + clamp(t, 0., 1.) - 1.) / length(tp));
        d = min(d, length(tp + 0.5 - p));
    }
    return d;
}
float fold(vec3 p) {
    for (int i = 0; i < 8; i++) p = abs(p) / dot(p, p) - vec3(0.5);
    return length(p);
}
"""
    findings = [f for f in lint_source(src, "x.glsl", FAST) if f.code == "PF004"]
    assert [(f.line, f.column) for f in findings] == [(5, 19)]
    assert "never uses i" in findings[0].message and "25 passes" in findings[0].message
    # the counter read through a local makes the passes differ
    used = src.replace("hash22(p) - .5", "hash22(p + i) - .5")
    assert found(used, "PF004") == []


def test_pf004_calls_of_functions_that_write_globals_are_not_moved() -> None:
    src = """float count;
float sample_(vec2 uv) { count += 1.0; return texture(iChannel0, uv + count).x; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float s = 0.0;
    for (int i = 0; i < 16; i++) s += sample_(fragCoord) * float(i);
    fragColor = vec4(s, count, 0.0, 1.0);
}
"""
    assert found(src, "PF004") == []


def test_pf002_leaves_texture_fetches_to_pf004() -> None:
    src = image(
        "    float s = 0.0;\n"
        "    for (int i = 0; i < 64; i++) s += texture(iChannel0, fragCoord).x * float(i);\n"
        "    fragColor = vec4(s);"
    )
    assert [code for code, _, _ in found(src)] == ["PF004"]


# --- PF003 ----------------------------------------------------------------------------------

UNITS = """const vec3 kSun = normalize(vec3(0.6, 0.8, -0.5));
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 rd = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    vec3 a = normalize(normalize(rd + kSun));
    vec3 b = normalize(rd);
    vec3 c = normalize(reflect(rd, kSun)).xzy;
    vec3 l = normalize(vec3(iMouse.xy, 1.0));
    vec3 d = normalize(-l);
    float e = normalize(-l).x;
    fragColor = vec4(a + b + c + d, e);
}
"""


def test_pf003_reports_normalize_of_unit_vectors() -> None:
    # normalize(-kSun) of the const kSun would be folded by the compiler: -l is a runtime value
    assert [line for _, line, _ in found(UNITS, "PF003")] == [4, 5, 6, 8, 9]


def test_pf003_fix_drops_the_outer_normalize() -> None:
    out = fixed(UNITS)
    assert "vec3 a = normalize(rd + kSun);" in out
    assert "vec3 b = rd;" in out
    assert "vec3 c = reflect(rd, kSun).xzy;" in out
    assert "vec3 d = -l;" in out
    assert "float e = (-l).x;" in out  # a field after it needs the parentheses
    assert fixed(out) == out and found(out, "PF003") == []


def test_pf003_keeps_normalize_of_parameters_and_rewritten_variables() -> None:
    src = """vec3 f(vec3 n) { return normalize(n); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 rd = normalize(vec3(fragCoord, 1.0));
    vec3 m = normalize(vec3(1.0));
    m = m * 2.0;
    vec3 k = normalize(m) + f(rd) + normalize(rd * 2.0);
    fragColor = vec4(k, 1.0);
}
"""
    assert found(src, "PF003") == []


@needs_glslang
def test_pf003_leaves_constants_and_comma_sequenced_writes_alone() -> None:
    text = image(
        "    vec3 up = normalize(vec3(0.0, 1.0, 0.0));\n"
        "    vec3 fwd = normalize(DIR);\n"
        "    vec3 m = vec3(0.0, 0.0, 1.0);\n"
        "    m = normalize(m);\n"
        "    vec3 no = normalize(vec3(fragCoord, 1.0));\n"
        "    if (fragCoord.x > 5.) no -= 0.2, no = normalize(no);\n"
        "    vec3 r = normalize(no);\n"
        "    fragColor = vec4(up + fwd + m + r, 1.0);",
        "const vec3 DIR = normalize(vec3(1.0, 2.0, 3.0));\n",
    )
    assert [line for _, line, _ in found(text, "PF003")] == [9]


def test_pf003_fixed_shader_validates() -> None:
    out = fixed(UNITS)
    assert [d for d in validate(out, "x.glsl", "shadertoy") if d.severity == "error"] == []


# --- the corpora ------------------------------------------------------------------------------


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_valid_corpus_has_no_performance_findings(path: Path) -> None:
    assert lint_source(path.read_text(encoding="utf-8"), str(path), FAST) == []


def test_a_loop_guard_reads_the_loop_condition_not_its_update_or_body() -> None:
    """`for (;; x += 1.0)` has no condition: its update is not one (nor, in `for (;;)`, its
    body); a while reads its condition and a do loop its trailing one."""
    from glint.compiler.glsl import parse, preprocess
    from glint.compiler.glsl.ast import SourceFile
    from glint.lint.analysis.invariance import Program, flow_of

    src = (
        "void f(float a, float b, float c, float d) {\n"
        "    float x = 0.0;\n"
        "    for (;; x += a) { break; }\n"
        "    for (;;) { x = b; break; }\n"
        "    for (; x < c;) { break; }\n"
        "    while (x < d) { break; }\n"
        "    do { break; } while (x < a);\n"
        "}\n"
    )
    body = SourceFile(parse(preprocess(src, "x.glsl").text)).functions[0].body
    flow = flow_of(Program(None, {}, set(), None), body)  # type: ignore[arg-type]
    guards = [set(w.reads) for w in flow.writes if w.target.startswith("#")]
    assert guards == [set(), set(), {"x", "c"}, {"x", "d"}, {"x", "a"}]


def test_pf004_tells_overloads_apart() -> None:
    """peek(x, y) is called in a loop with a varying y; peek(pos), the other overload, runs
    once: neither repeats a fetch with unchanged arguments."""
    src = """
vec4 peek(int x, int y) { return texelFetch(iChannel0, ivec2(x, y), 0); }
vec4 peek(int pos) { return texelFetch(iChannel0, ivec2(pos % 40, pos / 40), 0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec4 c = peek(int(fragCoord.x));
    for (int i = 0; i < 50; i++) {
        if (peek(0, i).x > 0.5) { c += 1.0; }
    }
    fragColor = c;
}
"""
    assert found(src, "PF004") == []


def test_pf004_an_event_that_turns_its_own_test_off_is_not_repeated() -> None:
    """startRound() runs when the round is over and moves the round's end on: it runs once per
    event, not on every pass of the loop around it. The same call under a test it does not
    change runs on every pass."""
    src = """
float gEnd = 0.0;
vec4 gState;
void startRound(float t) {
    gEnd = t + 10.0;
    gState = texelFetch(iChannel0, ivec2(3, 0), 0) + texelFetch(iChannel0, ivec2(4, 0), 0);
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    for (int k = 0; k < 64; k++) {
        float end = gEnd + 1.0;
        if (TEST) startRound(iTime);
    }
    fragColor = gState;
}
"""
    assert found(src.replace("TEST", "iTime > end"), "PF004") == []
    assert [f[0] for f in found(src.replace("TEST", "iTime > 5.0"), "PF004")] == ["PF004"]
