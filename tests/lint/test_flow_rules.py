"""Data-flow rules C101-C103 on the definite-assignment analysis: positives, negatives (the
analysis must stay quiet where it cannot be sure), and no recursion over long code."""

from __future__ import annotations

import inspect
import re
import sys

import pytest

from glint.lint.options import Options
from glint.lint.rules import all_rules, rule_doc
from glint.lint.rules.correctness.c101_colour_not_written import ColourNotWritten
from glint.lint.rules.correctness.c103_used_before_initialised import UsedBeforeInitialised
from glint.lint.runner import build_context, lint_source

FAST = Options(select=["P", "C1"], glslang=False)


def image(body: str, head: str = "") -> str:
    return f"{head}void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}\n}}\n"


def found(text: str) -> list[tuple[str, int]]:
    return [(f.code, f.line) for f in lint_source(text, "x.glsl", FAST)]


@pytest.mark.parametrize("code", ["C101", "C102", "C103"])
def test_rule_is_documented(code: str) -> None:
    rule = all_rules()[code]
    doc = rule_doc(rule)
    assert all(doc[k] for k in ("summary", "why", "example", "fix"))
    assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", rule.name) and rule.category == "correctness"


# --- C101 -----------------------------------------------------------------------------------


def test_c101_early_return() -> None:
    src = image("    if (fragCoord.x < 10.0) return;\n    fragColor = vec4(1.0);")
    assert found(src) == [("C101", 2)]


def test_c101_if_without_else() -> None:
    src = image("    if (fragCoord.x < 10.0) fragColor = vec4(1.0);")
    assert found(src) == [("C101", 1)]


def test_c101_never_written() -> None:
    findings = lint_source(image("    vec3 c = vec3(1.0);"), "x.glsl", FAST)
    assert [f.code for f in findings] == ["C101"] and "never writes" in findings[0].message


def test_c101_alpha_missing() -> None:
    findings = lint_source(image("    fragColor.rgb = vec3(1.0);"), "x.glsl", FAST)
    assert [f.code for f in findings] == ["C101"] and "fragColor.w" in findings[0].message


def test_c101_loop_that_may_not_run() -> None:
    src = image("    for (int i = 0; i < int(iTime); i++) fragColor = vec4(1.0);")
    assert found(src) == [("C101", 1)]


@pytest.mark.parametrize(
    "body",
    [
        "if (fragCoord.x < 1.0) discard;\nfragColor = vec4(1.0);",
        "if (fragCoord.x < 1.0) fragColor = vec4(0.0); else fragColor = vec4(1.0);",
        "fragColor = vec4(0.0);\nif (fragCoord.x < 1.0) return;\nfragColor.r = 1.0;",
        "fragColor.rgb = vec3(1.0);\nfragColor.a = 1.0;",
        "fragColor.xy = vec2(1.0); fragColor.z = 0.0; fragColor[3] = 1.0;",
        "switch (int(fragCoord.x) % 2) { case 0: fragColor = vec4(0.0); break;\n"
        "default: fragColor = vec4(1.0); }",
        "for (int i = 0; i < 4; i++) { fragColor = vec4(float(i)); }",
        "while (true) { fragColor = vec4(1.0); break; }",
        "do { fragColor = vec4(1.0); } while (false);",
        "render(fragColor, fragCoord);",
        "shade(fragColor);",
        "gl_FragColor = vec4(1.0);",  # P002's business
    ],
)
def test_c101_quiet_when_every_path_writes(body: str) -> None:
    head = "void shade(out vec4 c) { c = vec4(1.0); }\n"
    assert "C101" not in [c for c, _ in found(image(body, head))]


# --- C102 -----------------------------------------------------------------------------------


def test_c102_compound_assignment_first() -> None:
    src = image("    fragColor.rgb *= 0.5;\n    fragColor = vec4(1.0);")
    findings = lint_source(src, "x.glsl", FAST)
    assert [(f.code, f.line, f.column) for f in findings] == [("C102", 2, 5)]
    assert "fragColor.xyz" in findings[0].message


def test_c102_passed_to_an_inout_parameter() -> None:
    head = "void tint(inout vec4 c) { c *= 0.5; }\n"
    src = image("    tint(fragColor);", head)
    assert [c for c, _ in found(src)] == ["C102"]


def test_c102_quiet_after_a_write() -> None:
    src = image("fragColor = vec4(0.0);\nfragColor.rgb += vec3(0.5);\nfragColor.a *= 1.0;")
    assert found(src) == []
    src = image("fragColor.a = 1.0;\nfragColor.rgb = vec3(fragColor.a);")
    assert found(src) == []


@pytest.mark.parametrize(
    "body",
    [
        "fragColor -= fragColor; fragColor.rgb += vec3(1.0);",
        "fragColor *= 0.; fragColor += vec4(1.0);",
        "fragColor = fragColor - fragColor;",
        "fragColor.xyz = vec3(1.0); fragColor = fragColor*0. - vec4(0.5); fragColor.a = 1.;",
        "fragColor = 0.*fragColor + vec4(1.0);",
        "fragColor.rgb = vec3(1.0); fragColor *= 0.5;",  # only the (invisible) alpha is undefined
    ],
)
def test_c102_clearing_idioms_and_alpha_only(body: str) -> None:
    assert found(image(body)) == []


def test_c102_clearing_idiom_still_checks_the_rest() -> None:
    assert found(image("float d;\nfragColor = fragColor*0. - d;")) == [("C103", 3)]
    src = image("fragColor += fragColor * 0.;")  # += keeps the old value: not a clear
    assert [c for c, _ in found(src)] == ["C102"]


# --- C103 -----------------------------------------------------------------------------------


def test_c103_assigned_in_one_branch() -> None:
    src = image("    float d;\n    if (fragCoord.x > 1.0) d = 1.0;\n    fragColor = vec4(d);")
    findings = lint_source(src, "x.glsl", FAST)
    assert [(f.code, f.line, f.column) for f in findings] == [("C103", 4, 22)]
    assert "line 2" in findings[0].message


def test_c103_self_reference_and_loop_condition() -> None:
    assert found(image("float x;\nx = x + 1.0;\nfragColor = vec4(x);")) == [("C103", 3)]
    body = "float t;\nwhile (t < 1.0) { t = 2.0; }\nfragColor = vec4(t);"
    assert found(image(body)) == [("C103", 3)]


def test_c103_vector_components() -> None:
    src = image("vec3 v;\nv.xy = vec2(1.0);\nfragColor = vec4(v, 1.0);")
    findings = lint_source(src, "x.glsl", FAST)
    assert [f.code for f in findings] == ["C103"] and "`v.z`" in findings[0].message
    assert found(image("vec3 v;\nv.xy = vec2(1.0);\nfragColor = vec4(v.xy, v.x, 1.0);")) == []


def test_c103_loop_that_may_not_run() -> None:
    body = "float d;\nfor (int i = 0; i < int(iTime); i++) d = 1.0;\nfragColor = vec4(d);"
    assert found(image(body)) == [("C103", 4)]


def test_c104_out_parameter_read_first() -> None:
    head = "void f(out float o, float k) { o += k; }\n"
    assert found(image("float x; f(x, 1.0); fragColor = vec4(x);", head)) == [("C104", 1)]


def test_c103_short_circuit_writes_do_not_count() -> None:
    body = "float x;\nif (fragCoord.x > 0.0 && (x = 1.0) > 0.0) { }\nfragColor = vec4(x);"
    assert found(image(body)) == [("C103", 4)]


@pytest.mark.parametrize(
    "body",
    [
        "float d; if (fragCoord.x > 1.0) d = 1.0; else d = 2.0; fragColor = vec4(d);",
        "float d; for (int i = 0; i < 8; i++) { d = float(i); if (d > 3.0) break; }"
        " fragColor = vec4(d);",
        "float d; for (int i = 0; i < STEPS; i++) { d = float(i); } fragColor = vec4(d);",
        "float d; while (true) { d = 1.0; if (fragCoord.x > d) break; } fragColor = vec4(d);",
        "float d; do { d = 1.0; } while (d < 0.0); fragColor = vec4(d);",
        "float d; switch (int(fragCoord.x)) { case 0: d = 0.0; break; default: d = 1.0; }"
        " fragColor = vec4(d);",
        "float d; int k = int(fragCoord.x); if (k == 0) { d = 0.0; } else if (k == 1) { d = 1.0; }"
        " else { discard; } fragColor = vec4(d);",
        "float d; set(d); fragColor = vec4(d);",  # the file's own out parameter
        "float ip; float f = modf(fragCoord.x, ip); fragColor = vec4(ip + f);",
        "float d; elsewhere(d); fragColor = vec4(d);",  # not in this file: unsure, so quiet
        "float w[3]; w[0] = 1.0; fragColor = vec4(w[2]);",  # arrays: any write counts
        "Hit h; h.t = 1.0; h.id = 2.0; fragColor = vec4(h.t, h.id, 0.0, 1.0);",
        "Hit h; h = Hit(1.0, 2.0); fragColor = vec4(h.t, h.id, 0.0, 1.0);",
        "Hit h; h.t = 1.0; fragColor = vec4(h.t);",  # the member read is written
        "float w[3]; int n = w.length(); fragColor = vec4(float(n));",
        "mat2 m; m[0] = vec2(1.0); m[1] = vec2(0.0); fragColor = vec4(m[0], m[1]);",
        "float a, b; a = b = 1.0; fragColor = vec4(a + b);",
        "float x; x = 1.0; { float x; x = 2.0; } fragColor = vec4(x);",
        "float d; if (fragCoord.x > 1.0) { d = 1.0; } else { discard; } fragColor = vec4(d);",
        "float d = 1.0; fragColor = vec4(d);",
        "float d; fragColor = vec4(1.0); return; fragColor = vec4(d);",  # dead code
    ],
)
def test_c103_quiet_when_assigned_or_unsure(body: str) -> None:
    head = "const int STEPS = 4;\nstruct Hit { float t; float id; };\n" \
           "void set(out float v) { v = 1.0; }\n"  # fmt: skip
    assert found(image(body, head)) == []


# --- conditions, loop bounds and callee summaries ------------------------------------------


@pytest.mark.parametrize(
    "loop",
    [
        "for (float i = 1.5; i > 0.; i -= .002)",
        "for (float i = 8.; i > 0.; --i)",
        "for (float i = 0.; i < ITER; i++)",  # a const float
        "for (int i = N - 1; i >= 0; i--)",  # const arithmetic
        "for (float i = 0.; 20. > i; i++)",  # the bound on the left
    ],
)
def test_loops_with_numeric_constant_bounds_run(loop: str) -> None:
    head = "const float ITER = 5.;\nconst int N = 4;\n"
    body = f"float d;\n{loop} {{ d = 1.0; fragColor = vec4(d); }}\nfragColor.rgb *= d;"
    assert found(image(body, head)) == []
    # a loop that may not run still leaves them unwritten
    body = "float d;\nfor (float i = 0.; i < iTime; i++) { d = 1.0; }\nfragColor = vec4(d);"
    assert found(image(body, head)) == [("C103", 6)]


def test_and_condition_true_means_both_sides_ran() -> None:
    head = "bool get(out vec3 v) { v = vec3(1.0); return true; }\n"
    body = ("vec3 v; fragColor = vec4(0.0);\n"
            "if (fragCoord.x > 1.0 && get(v)) fragColor.rgb = v;\n"
            "else fragColor.rgb = v;")  # fmt: skip
    # the else joins (x <= 1: get did not run) and (get returned false): v may be unset
    assert found(image(body, head)) == [("C103", 5)]
    body = ("vec3 v; fragColor = vec4(0.0);\n"
            "if (fragCoord.x > 1.0 || !get(v)) { } else fragColor.rgb = v;\n"
            "fragColor.rgb = v;")  # fmt: skip
    # || false: both sides ran; after the if, v is still unsure
    assert found(image(body, head)) == [("C103", 5)]
    body = "vec3 v; fragColor = (fragCoord.x > 1.0 && get(v)) ? vec4(v, 1.0) : vec4(0.0);"
    assert found(image(body, head)) == []


def test_condition_decided_by_value_ranges() -> None:
    body = "float d;\nif (fract(fragCoord.x) < 2.0) d = 1.0;\nfragColor = vec4(d);"
    assert found(image(body)) == []
    body = "float d;\nif (fract(fragCoord.x) > 2.0) fragColor = vec4(d);\nfragColor = vec4(1.0);"
    assert found(image(body)) == []  # a branch that is never taken reads nothing
    body = "float d;\nif (fract(fragCoord.x) < 0.5) d = 1.0;\nfragColor = vec4(d);"
    assert found(image(body)) == [("C103", 4)]  # may be either: still reported


def test_inout_parameter_the_callee_only_writes_is_an_out() -> None:
    head = "float march(inout float t, inout bool hit) { t = 0.; hit = false; return t; }\n"
    body = "float t; bool hit; float d = march(t, hit); fragColor = vec4(t, d, 0.0, 1.0);"
    assert found(image(body, head)) == []
    head = "void shade(inout float t) { t = t * 2.0; }\n"
    assert found(image("float t; shade(t); fragColor = vec4(t);", head)) == [("C103", 3)]


def test_inout_summary_names_the_components_read_first() -> None:
    head = "void mode(inout vec4 o, vec2 i) { o.xy = i; o = mod(o, .8); }\n"
    findings = lint_source(image("mode(fragColor, fragCoord);", head), "x.glsl", FAST)
    assert [f.code for f in findings] == ["C102"] and "fragColor.zw" in findings[0].message
    # transitively: a function passing its own inout on inherits the callee's reads
    head += "void wrap(inout vec4 c) { c.w = 1.0; mode(c, vec2(0.0)); }\n"
    findings = lint_source(image("wrap(fragColor);", head), "x.glsl", FAST)
    assert [f.code for f in findings] == ["C102"] and "`fragColor.z`" in findings[0].message


def test_loop_that_surely_runs_is_peeled_at_its_first_iteration() -> None:
    body = ("float d = 1e9; vec2 prev, first;\n"
            "for (int i = 0; i < 8; i++) {\n"
            "  vec2 q = vec2(float(i));\n"
            "  if (i == 0) first = q; else d = min(d, distance(q, prev));\n"
            "  prev = q;\n"
            "}\n"
            "fragColor = vec4(d, first, 1.0);")  # fmt: skip
    assert found(image(body)) == []
    # a loop that may not run is not peeled; nor one whose counter the body changes
    assert found(image(body.replace("i < 8", "i < int(iTime)"))) != []
    assert found(image(body.replace("prev = q;", "prev = q; i += 0;"))) != []
    # the later iterations still see what the first leaves unset
    body = body.replace("prev = q;", "").replace("vec2 prev, first;", "vec2 prev, first;")
    assert [c for c, _ in found(image(body))] == ["C103"]


# --- robustness -----------------------------------------------------------------------------


def test_long_bodies_and_chains_do_not_recurse() -> None:
    statements = "\n".join("x = x + 1.0;" for _ in range(4000))
    chain = " + ".join(["x"] * 400)  # the parser itself gives up (C006) a little beyond this
    src = image(f"float x = 0.0;\n{statements}\nfloat y = {chain};\nfragColor = vec4(y);")
    ctx = build_context(src, "x.glsl", FAST)
    assert ctx.tree is not None
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(len(inspect.stack()) + 200)  # far less than the chain is deep
    try:
        assert list(ColourNotWritten().check(ctx)) == []
        assert list(UsedBeforeInitialised().check(ctx)) == []
    finally:
        sys.setrecursionlimit(limit)


def test_colour_written_on_one_path_is_not_called_never_written() -> None:
    from glint.lint.options import Options
    from glint.lint.runner import lint_source

    text = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    if (fragCoord.x > 0.0) { fragColor = vec4(1.0); }\n}\n"
    )
    found = lint_source(text, "x.glsl", Options(select=["C101"], glslang=False))
    assert [f.code for f in found] == ["C101"]
    assert "not written on every path" in found[0].message


def test_a_file_testing_a_macro_it_does_not_define_is_still_analysed() -> None:
    body = "float d;\n#if CACHE > 0\nd = 1.0;\n#endif\nfragColor = vec4(d);"
    findings = lint_source(image(body), "x.glsl", Options(select=["C004", "C103"], glslang=False))
    assert [(f.code, f.line) for f in findings] == [("C004", 3), ("C103", 6)]


# --- issue 26: one finding per variable, tied conditions, case analyses, members, C105 --------


def located(text: str) -> list[tuple[str, int, int]]:
    return [(f.code, f.line, f.column) for f in lint_source(text, "x.glsl", FAST)]


def test_c103_one_finding_per_variable_at_the_declaration_when_read_twice() -> None:
    body = ("vec4 pick;\nif (iMouse.z > 0.) pick = vec4(1.);\n"
            "if (iMouse.x > 0.) fragColor = pick;\nelse fragColor = pick * 2.;")  # fmt: skip
    findings = lint_source(image(body), "x.glsl", FAST)
    assert [(f.code, f.line, f.column) for f in findings] == [("C103", 2, 6)]
    assert "lines 4 and 5" in findings[0].message and "line 3" in findings[0].message
    body = "vec4 pick;\nif (iMouse.z > 0.) pick = vec4(1.);\nfragColor = pick;"
    assert located(image(body)) == [("C103", 4, 13)]  # one read: at the read


def test_c103_quiet_where_the_read_is_under_a_condition_tied_to_the_write() -> None:
    flag = ("fragColor = vec4(0.); vec3 n; bool hit = false;\n"
            "if (fragCoord.x > 1.) { hit = true; n = vec3(1.); }\n")  # fmt: skip
    assert found(image(flag + "if (hit) fragColor = vec4(n, 1.);")) == []
    sentinel = ("fragColor = vec4(0.); vec3 n; float tmin = 1e20;\nfor (int i = 0; i < 4; i++) {\n"
                "  float t = float(i) - fragCoord.x;\n"
                "  if (t > 0. && t < tmin) { tmin = t; n = vec3(t); }\n}\n")  # fmt: skip
    assert found(image(sentinel + "if (tmin < 1e19) fragColor = vec4(n, 1.);")) == []
    # an unrelated condition at the read does not excuse it
    assert found(image(flag + "if (fragCoord.y > 1.) fragColor = vec4(n, 1.);")) == [("C103", 4)]
    assert found(image(sentinel + "fragColor = vec4(n, 1.);")) == [("C103", 7)]


def test_c103_case_analyses_of_one_value_are_exhaustive() -> None:
    ids = "float c; int k = int(fragCoord.x) % 2;\nif (k == 0) c = 1.;\nif (k == 1) c = 2.;\n"
    assert found(image(ids + "fragColor = vec4(c);")) == []
    chain = ("float c; float t = fract(iTime);\nif (t < .3) c = 1.;\nelse if (t < .6) c = 2.;\n"
             "else if (t < 1.) c = 3.;\n")  # fmt: skip
    assert found(image(chain + "fragColor = vec4(c);")) == []
    either = "float c;\nif (iMouse.x < 1.) c = 1.;\nelse if (iMouse.y < 1.) c = 2.;\n"
    assert found(image(either + "fragColor = vec4(c);")) == [("C103", 5)]  # two values
    # the value changes in a case: not a case analysis
    moved = (
        "float c; int k = int(fragCoord.x);\nif (k == 0) { c = 1.; k = 1; }\nif (k == 1) k = 2;\n"
    )
    assert found(image(moved + "fragColor = vec4(c);")) == [("C103", 5)]


def test_c103_struct_member_read_by_the_callee() -> None:
    head = ("struct Surf { vec3 n; vec3 tra; };\n"
            "vec3 shade(in Surf s, float k) {\n  return mix(s.n, s.tra, k);\n}\n")  # fmt: skip
    body = "Surf s; s.n = vec3(1.);\nfragColor = vec4(shade(s, 0.), 1.);"
    findings = lint_source(image(body, head), "x.glsl", FAST)
    assert [(f.code, f.line) for f in findings] == [("C103", 3)]  # at the callee's read
    assert "`s.tra`" in findings[0].message and "line 7" in findings[0].message
    body = "Surf s; s.n = vec3(1.); s.tra = vec3(0.);\nfragColor = vec4(shade(s, 0.), 1.);"
    assert found(image(body, head)) == []
    head2 = "struct Hit { float t; float id; };\n" \
            "Hit f(float x) { Hit h; if (x > 0.) h.t = x; return h; }\n"  # fmt: skip
    src = image("fragColor = vec4(f(fragCoord.x).t);", head2)
    findings = lint_source(src, "x.glsl", FAST)
    # h.id is read nowhere: only the member read (h.t) is named
    assert [f.code for f in findings] == ["C103"] and "`h.t`" in findings[0].message


def test_c104_reported_once_per_parameter() -> None:
    head = "float f(out float n) { n += 1.; n *= 2.; if (n > 1.) n -= 1.; return n; }\n"
    assert found(image("float x; float y = f(x); fragColor = vec4(x, y, 0., 1.);", head)) == [
        ("C104", 1)
    ]


@pytest.mark.parametrize(
    ("head", "reported"),
    [
        ("float f(float x) { if (x > 0.) return 1.; }\n", True),
        ("float f(float x) { for (int i = 0; i < 4; i++) { if (x > 0.) return 1.; } }\n", True),
        ("float f(float x) { x *= 2.; }\n", True),
        ("float f(float x) { if (x > 0.) return 1.; else return 2.; }\n", False),
        ("float f(float x) { for (;;) { if (x > 0.) return 1.; x += 1.; } }\n", False),
        ("float f(float x) { while (true) { if (x > 0.) return 1.; x += 1.; } }\n", False),
        ("float f(float x) { if (x > 0.) return 1.; discard; }\n", False),
        ("float f(float x) { switch (int(x)) { case 0: return 0.; default: return 1.; } }\n",
         False),
    ],
)  # fmt: skip
def test_c105_missing_return(head: str, reported: bool) -> None:
    src = image("fragColor = vec4(f(fragCoord.x));", head)
    assert found(src) == ([("C105", 1)] if reported else [])
    # a function nobody calls is not reported
    assert found(image("fragColor = vec4(1.);", head)) == []


# --- values known on the first iteration (known_values.py) ----------------------------------

_MARCH_HEAD = (
    "struct Ray { vec3 o; vec3 d; float len; };\n"
    "struct Model { float dist; int id; };\n"
    "Model map(vec3 p) { return Model(length(p) - 1.0, 1); }\n"
    "float scene(vec3 p, out vec4 m) { m = vec4(p, 1.0); return length(p) - 1.0; }\n"
    "const float EPS = 0.001;\nconst float FAR = 20.0;\nconst int STEPS = 64;\n"
)


@pytest.mark.parametrize(
    "march",
    [
        # the break's condition is false with the values set before the loop
        "float d = EPS * 2.0; float t = 0.0; Model m;\n"
        "for (int i = 0; i < STEPS; i++) {\n"
        "  if (d < EPS || t > FAR) break;\n"
        "  m = map(vec3(t)); d = m.dist; t += d; }\n"
        "fragColor = vec4(m.dist);",
        # through a member of a struct built by its constructor
        "float d = 2.0 * EPS; Model m; Ray ray = Ray(vec3(0), vec3(1), 0.);\n"
        "for (int i = 0; i < STEPS; i++) {\n"
        "  if (d < EPS || ray.len > FAR) { break; }\n"
        "  m = map(ray.o + ray.d * ray.len); d = m.dist; ray.len += d; }\n"
        "fragColor = vec4(m.dist);",
        # an out argument, and a loop without a condition
        "vec4 tmp; float h = 1.0; float t = 0.0;\n"
        "for (;;) { if (h < 0.0001 || t > 10.0) break; h = scene(vec3(t), tmp); t += h; }\n"
        "fragColor = tmp;",
        # a while loop whose first test passes
        "vec4 tmp; float t = 0.0;\nwhile (t < FAR) { t += scene(vec3(t), tmp); }\nfragColor = tmp;",
    ],
)
def test_c103_first_iteration_of_a_march_does_not_break(march: str) -> None:
    assert found(image(march, _MARCH_HEAD)) == []


@pytest.mark.parametrize(
    "march",
    [
        # the first iteration may break: the starting distance is not above the threshold
        "float d = EPS * 0.5; Model m;\n"
        "for (int i = 0; i < STEPS; i++) { if (d < EPS) break; m = map(vec3(1)); d = m.dist; }\n"
        "fragColor = vec4(m.dist);",
        # the value the break tests is unknown (a parameter of the frame)
        "float t = iTime; Model m;\n"
        "for (int i = 0; i < STEPS; i++) { if (t > FAR) break; m = map(vec3(t)); t += m.dist; }\n"
        "fragColor = vec4(m.dist);",
        # changed in the body before the test: the value before the loop no longer holds
        "float t = 0.0; Model m;\n"
        "for (int i = 0; i < STEPS; i++) { t = iTime; if (t > FAR) break; m = map(vec3(t)); }\n"
        "fragColor = vec4(m.dist);",
        # changed in a branch before the loop: either value may hold
        "float t = 0.0; Model m;\nif (fragCoord.x > 9.0) t = 100.0;\n"
        "for (int i = 0; i < STEPS; i++) { if (t > FAR) break; m = map(vec3(t)); }\n"
        "fragColor = vec4(m.dist);",
        # `t = t + 30.`: the new value, not the old one, is tested at the break
        "float t = 0.0; Model m;\nt = t + 30.0;\n"
        "for (int i = 0; i < STEPS; i++) { if (t > FAR) break; m = map(vec3(t)); }\n"
        "fragColor = vec4(m.dist);",
        # the loop may not run at all: the while test is decided by nothing known
        "vec4 tmp; float t = iTime;\nwhile (t < FAR) { t += scene(vec3(t), tmp); }\n"
        "fragColor = tmp;",
    ],
)
def test_c103_march_that_may_break_at_once_is_still_reported(march: str) -> None:
    assert [c for c, _ in found(image(march, _MARCH_HEAD))] == ["C103"]


def test_c103_value_known_in_an_outer_loop_holds_only_on_its_first_iteration() -> None:
    # t changes at the end of each outer iteration: on the second, the inner loop may break
    # at once and leave that iteration's r unset; t = 0.0 decides only the first
    src = image(
        "float t = 0.0;\n"
        "for (int k = 0; k < 3; k++) {\n"
        "  float r;\n"
        "  for (int i = 0; i < 4; i++) { if (t > 5.0) break; r = float(i); }\n"
        "  fragColor = vec4(r);\n"
        "  t = iTime; }",
    )
    assert [c for c, _ in found(src)] == ["C103"]
    assert found(src.replace("t = iTime;", "")) == []


_VORONOI_HEAD = "vec2 hash(vec2 p) { return fract(sin(p * 591.32) * 43758.5); }\n"


def _nearest_point_loop(start: str) -> str:
    """A 3x3 nearest-point search (Chebyshev distance) whose bound starts at `start`."""
    return image(
        "vec2 x = fragCoord / 40.0; vec2 n = floor(x); vec2 f = fract(x);\n"
        f"vec2 mr; float md = {start};\n"
        "for (int j = -1; j <= 1; j++)\n"
        "for (int i = -1; i <= 1; i++) {\n"
        "  vec2 g = vec2(float(i), float(j)); vec2 o = hash(n + g); vec2 r = g + o - f;\n"
        "  float d = max(abs(r.x), abs(r.y));\n"
        "  if (d < md) { md = d; mr = r; } }\n"
        "fragColor = vec4(mr, md, 1.0);",
        _VORONOI_HEAD,
    )


def test_c103_nearest_point_loop_writes_on_its_first_iteration() -> None:
    # the Chebyshev distance to the first cell's point is below 2, under the starting 8.0
    assert found(_nearest_point_loop("8.0")) == []


@pytest.mark.parametrize(
    "start",
    [
        "1.0",  # the first cell's point may be farther than 1.0
        "iTime",  # nothing known of the starting bound
    ],
)
def test_c103_nearest_point_loop_with_a_bound_it_may_not_beat(start: str) -> None:
    assert [c for c, _ in found(_nearest_point_loop(start))] == ["C103"]


def test_c103_value_stored_in_one_branch_is_not_known_in_the_other() -> None:
    src = image(
        "float t = 0.0; float r;\n"
        "if (fragCoord.x > 9.0) { t = 100.0; } else {\n"
        "  for (int i = 0; i < 4; i++) { if (t > 5.0) break; r = 1.0; } }\n"
        "if (fragCoord.x > 9.0) { for (int i = 0; i < 4; i++) { if (t > 5.0) break; r = 2.0; } }\n"
        "fragColor = vec4(r);",
    )
    assert [c for c, _ in found(src)] == ["C103"]


# --- C103: searches taken on some iteration, members nothing reads, flags -----------------------

_SEARCH = (
    "vec2 x = fragCoord / 40.0; vec2 n = floor(x); vec2 f = fract(x);\n"
    "vec2 mr, mg; float md = {start};\n"
    "for (int j = -1; j <= 1; j++)\n"
    "for (int i = -1; i <= 1; i++) {{\n"
    "  vec2 g = vec2(float(i), float(j)); vec2 o = hash(n + g);\n"
    "  o = 0.5 + 0.5 * sin(iTime + 6.2831 * o);\n"
    "  vec2 r = g + o - f; float d = dot(r, r);\n"
    "  {test} {{ md = d; mr = r; mg = g; }} }}\n"
    "fragColor = vec4(mr, mg);"
)


@pytest.mark.parametrize("start", ["8.0", "3.0", "1e20"])
def test_c103_search_taken_on_some_iteration(start: str) -> None:
    # the first cell (-1, -1) may lie farther than 3.0 (d up to 8), but the middle cell's
    # point is nearer than 2: the branch runs there or before, so mr and mg are set
    src = image(_SEARCH.format(start=start, test="if (d < md)"), _VORONOI_HEAD)
    assert found(src) == []


@pytest.mark.parametrize(
    ("start", "test"),
    [
        ("2.0", "if (d < md)"),  # even the middle cell's d may reach 2
        ("iTime", "if (d < md)"),  # nothing known of the start
        ("8.0", "if (d < md && fragCoord.x > 9.0)"),  # another condition may fail
        ("8.0", "if (d < md) md = 0.0; if (d < md)"),  # md changes outside the branch
        ("8.0", "if (i == 9) break; if (d < md)"),  # a loop that may stop early
    ],
)
def test_c103_search_that_may_never_take_its_branch(start: str, test: str) -> None:
    src = image(_SEARCH.format(start=start, test=test), _VORONOI_HEAD)
    assert {c for c, _ in found(src)} == {"C103"}  # mr, mg


def test_c103_search_in_a_loop_that_may_not_run() -> None:
    src = image(
        _SEARCH.format(start="8.0", test="if (d < md)").replace("i <= 1", "i <= iFrame"),
        _VORONOI_HEAD,
    )
    assert {c for c, _ in found(src)} == {"C103"}  # mr, mg


_MATERIAL = (
    "struct Mat { vec3 col; float spec; float par; };\n"
    "Mat material(float id) {\n"
    "  Mat m; m.col = vec3(1.); m.spec = 0.5;\n"
    "  if (id > 1.) m.par = 1.;\n"
    "  return m;\n"
    "}\n"
)


def test_c103_returned_member_nothing_reads_is_not_reported() -> None:
    body = "Mat m = material(fragCoord.x);\nfragColor = vec4(m.col * m.spec, 1.);"
    assert found(image(body, _MATERIAL)) == []


def test_c103_returned_member_read_somewhere_is_reported() -> None:
    body = "Mat m = material(fragCoord.x);\nfragColor = vec4(m.col * m.par, 1.);"
    findings = lint_source(image(body, _MATERIAL), "x.glsl", FAST)
    assert [(f.code, f.line) for f in findings] == [("C103", 5)]
    assert "`m.par`" in findings[0].message
    # written only (`m.par = 0.`) is not read; compared whole (`==`) reads every member
    body = "Mat m = material(fragCoord.x); m.par = 0.;\nfragColor = vec4(m.col, 1.);"
    assert found(image(body, _MATERIAL)) == []
    body = "Mat a = material(1.), b = material(2.);\nfragColor = vec4(a == b ? 1. : 0.);"
    assert [c for c, _ in found(image(body, _MATERIAL))] == ["C103"]


_FLAG = (
    "vec3 col; bool ground = false;\n"
    "if (fragCoord.y > 100.) col = vec3(1.);\n"
    "else if (fragCoord.x > 50.) ground = true;\n"
    "else col = vec3(0.);\n"
)


def test_c103_flag_set_where_the_write_is_left_to_a_later_branch() -> None:
    body = _FLAG + "if (ground) col = vec3(0.5);\nfragColor = vec4(col, 1.);"
    assert found(image(body)) == []
    body = _FLAG + "if (!ground) {} else { col = vec3(0.5); }\nfragColor = vec4(col, 1.);"
    assert found(image(body)) == []


@pytest.mark.parametrize(
    "between",
    [
        "ground = fragCoord.x > 60.;",  # the flag changed to anything but true
        "",  # the flag is not tested before the read
    ],
)
def test_c103_flag_that_no_longer_promises_the_write(between: str) -> None:
    test = "if (ground) col = vec3(0.5);\n" if between else ""
    body = _FLAG + between + "\n" + test + "fragColor = vec4(col, 1.);"
    assert [c for c, _ in found(image(body))] == ["C103"]
