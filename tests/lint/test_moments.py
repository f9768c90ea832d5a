"""Exact values at named moments (lint/analysis/moments/) and the rules that read them: N011
division-by-zero-at-moment and N012 domain-at-moment. Each case is a small shader that must be
reported on one line, next to a nearby one that must not be."""

from __future__ import annotations

from lark import Tree

from glint.lint.analysis.moments import MAX_VARIANTS, Moments
from glint.lint.finding import Finding
from glint.lint.options import Options
from glint.lint.runner import build_context, lint_source

MOMENTS = Options(select=["N011", "N012"], glslang=False)


def lint(src: str) -> list[Finding]:
    return lint_source(src, "t.glsl", MOMENTS)


def lines(src: str, code: str = "N011") -> list[int]:
    return [f.line for f in lint(src) if f.code == code]


def line_of(src: str, needle: str) -> int:
    return next(i for i, text in enumerate(src.split("\n"), 1) if needle in text)


def main(body: str, helpers: str = "") -> str:
    return (
        helpers
        + "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        + "    vec2 uv = fragCoord / iResolution.xy;\n"
        + body
        + "\n}\n"
    )


SHADOW = """
float shadow(vec3 ro, vec3 rd, float start) {
    float res = 1.0;
    float t = START;
    for (int i = 0; i < 32; i++) {
        float h = length(ro + rd * t) - 1.0;
        res = min(res, 8.0 * h / t);
        t += clamp(h, 0.02, 0.5);
    }
    return res;
}
"""

CALL = "fragColor = vec4(shadow(vec3(uv, 2.0), vec3(0.0, 0.0, -1.0), {}));"


# --- the first iteration of a loop ----------------------------------------------------------


def test_a_loop_dividing_by_its_starting_zero_is_reported_on_the_first_iteration() -> None:
    src = main(CALL.format(0.0), SHADOW.replace("START", "0.0"))
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "8.0 * h / t")
    assert (
        "divides by t, which is 0.0 on the first iteration of the loop at line" in finding.message
    )
    assert "(t = 0.0 before it)" in finding.message
    assert "advance it before dividing" in finding.message


def test_a_loop_starting_away_from_zero_is_not_reported() -> None:
    src = main(CALL.format(0.0), SHADOW.replace("START", "0.02"))
    assert lines(src) == []
    src = main(CALL.format(0.02), SHADOW.replace("START", "start"))
    assert lines(src) == []


def test_a_zero_start_passed_by_the_caller_is_reported_at_the_call() -> None:
    src = main(CALL.format(0.0), SHADOW.replace("START", "start"))
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "shadow(vec3(uv")
    assert "makes shadow() divide by t" in finding.message and "start = 0.0" in finding.message


def test_a_division_guarded_by_a_test_of_the_divisor_is_not_reported() -> None:
    src = main(
        """
    float t = 0.0, res = 1.0;
    for (int i = 0; i < 8; i++) {
        float h = uv.x - float(i);
        if (t > 0.0) res = min(res, h / t);
        t += 0.1;
    }
    fragColor = vec4(res);"""
    )
    assert lines(src) == []


def test_after_a_loop_what_it_assigns_is_unknown() -> None:
    src = main(
        """
    float t = 0.0;
    for (int i = 0; i < 8; i++) { t += uv.x; }
    fragColor = vec4(1.0 / t);"""
    )
    assert lines(src) == []


def test_a_loop_that_never_runs_keeps_its_variables() -> None:
    src = main(
        """
    float n = 0.0;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 0; i++) { sum += vec4(uv, 0.0, 1.0); n += 1.0; }
    fragColor = sum / n;"""
    )
    assert lines(src) == [line_of(src, "sum / n")]


# --- the first frame and the first click ----------------------------------------------------


def test_a_divisor_that_is_zero_at_the_first_frame_is_reported_with_0_over_0() -> None:
    src = main(
        """
    float sec = mod(iTime, 1.0);
    fragColor = vec4(sin(sec * 50.0) / sqrt(sec));"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "sqrt(sec)")
    assert "at the first frame (iTime = 0)" in finding.message
    assert "(0/0: NaN)" in finding.message


def test_an_offset_time_and_an_unknown_divisor_are_not_reported() -> None:
    src = main(
        """
    float sec = mod(iTime, 1.0) + 0.5;
    float r = uv.x / length(uv - 0.5);
    fragColor = vec4(sin(sec) / sqrt(sec), r, 0.0, 1.0);"""
    )
    assert lines(src) == []


def test_an_infinity_that_only_reaches_a_clamp_is_not_reported() -> None:
    # 1 / 0 is +inf, not NaN, and clamp bounds it: harmless
    src = main("fragColor = vec4(clamp(0.1 + 1.0 / iTime * 0.05, 0.0, 10.0));")
    assert lines(src) == []


def test_normalize_of_the_unclicked_mouse_is_a_domain_finding() -> None:
    src = main(
        """
    vec2 dir = normalize(iMouse.xy);
    vec2 safe = iMouse.z > 0.0 ? normalize(iMouse.xy) : vec2(1.0, 0.0);
    fragColor = vec4(dir, safe);"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N012"]
    assert finding.line == line_of(src, "vec2 dir")
    assert "until the first mouse click" in finding.message


def test_log_and_sqrt_outside_their_domain_at_a_moment() -> None:
    src = main(
        """
    float a = log(iTime);
    float b = sqrt(iTime - 1.0);
    float c = log(iTime + 1.0);
    float d = sqrt(iTime);
    fragColor = vec4(a, b, c, d);"""
    )
    assert lines(src, "N012") == [line_of(src, "log(iTime)"), line_of(src, "sqrt(iTime - 1.0)")]


def test_mod_by_zero_and_atan_of_the_origin_at_a_moment() -> None:
    src = main(
        """
    float a = mod(uv.x, iTime);
    float b = atan(iMouse.y, iMouse.x);
    float c = atan(iMouse.y, 1.0);
    fragColor = vec4(a, b, c, 1.0);"""
    )
    assert lines(src) == [line_of(src, "mod(uv.x"), line_of(src, "atan(iMouse.y, iMouse.x)")]


def test_a_branch_taken_at_the_first_frame_sets_what_follows() -> None:
    src = main(
        """
    vec3 vel = texture(iChannel0, uv).xyz;
    if (iFrame == 0) vel = vec3(0.0);
    vel.xy *= (length(vel.xy) - iTimeDelta) / length(vel.xy);
    fragColor = vec4(vel, 1.0);"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "vel.xy *=")
    assert "at the first frame" in finding.message and "(0/0: NaN)" in finding.message


# --- call sites ----------------------------------------------------------------------------

TL = """
float sum = 0.0;
float tl(float val, float offset, float range) {
    float im = sum + offset;
    float ix = im + range;
    sum += offset + range;
    return clamp((val - im) / (ix - im), 0.0, 1.0);
}
"""


def test_constants_passed_at_a_call_site_are_reported_there_naming_the_call() -> None:
    src = main(
        """
    float t = tl(uv.x, 1.0, 0.5);
    t += tl(uv.x, 0.0, 0.0);
    fragColor = vec4(t);""",
        TL,
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "tl(uv.x, 0.0, 0.0)")
    assert "tl(uv.x, 0.0, 0.0) makes tl() divide by ix - im" in finding.message
    assert "range = 0.0" in finding.message


def test_one_finding_per_defect_of_a_callee() -> None:
    src = main(
        """
    float t = tl(uv.x, 0.0, 0.0) + tl(uv.y, 0.0, 0.0) + tl(uv.y, 2.0, 0.0);
    fragColor = vec4(t);""",
        TL,
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert "(and 2 more calls like it)" in finding.message


def test_a_callee_evaluated_once_per_constant_tuple_and_at_most_a_few_times() -> None:
    calls = " + ".join(f"tl(uv.x, {i}.0, 1.0)" for i in range(1, 60))
    src = main(f"fragColor = vec4({calls});", TL)
    ctx = build_context(src, "t.glsl", MOMENTS)
    assert isinstance(ctx.tree, Tree)
    moments = Moments(ctx.tree)
    (fn,) = moments.functions["tl"]
    assert fn.variants <= MAX_VARIANTS + 1
    assert len(moments._memo) <= MAX_VARIANTS + 3  # mainImage, tl's variants, tl with unknowns


def test_a_global_a_callee_does_not_write_keeps_its_value_after_the_call() -> None:
    src = main(
        """
    float k = 0.0;
    if (MODE == 1) k = 1.0 / zero(uv.x);
    if (MODE == 0) k = helper(uv.x);
    if (MODE == 1) k = 1.0 / zero(uv.y);
    fragColor = vec4(k);""",
        """
int MODE = 0;
float zero(float x) { return x * 0.0; }
float helper(float x) { return x + 1.0; }
""",
    )
    assert lines(src) == []


def test_an_inout_argument_is_unknown_after_the_call() -> None:
    src = main(
        """
    float d = 0.0;
    grow(d, uv.x);
    fragColor = vec4(1.0 / d);""",
        "void grow(inout float d, float by) { d += by; }\n",
    )
    assert lines(src) == []


def test_a_branch_the_value_range_rules_out_is_not_taken() -> None:
    # dot(z, z) < 0.0 never holds, so the division by the zero passed in never runs
    src = main(
        """
    vec3 p = vec3(uv, 1.0);
    fold(p, 0.0);
    fragColor = vec4(p, 1.0);""",
        """
void fold(inout vec3 z, float r) {
    float r2 = dot(z, z);
    if (r2 < r) z *= 2.0 / r;
}
""",
    )
    assert lines(src) == []


def test_two_calls_of_one_function_return_different_unknowns() -> None:
    # map(p + e) - map(p - e) is not 0: each call returns its own unknown
    src = main(
        """
    vec2 e = vec2(0.001, 0.0);
    vec3 p = vec3(uv, 0.0);
    vec3 n = normalize(vec3(map(p + e.xyy) - map(p - e.xyy), map(p + e.yxy) - map(p - e.yxy),
                            map(p + e.yyx) - map(p - e.yyx)));
    fragColor = vec4(n, 1.0);""",
        "float map(vec3 p) { return length(p) - 1.0; }\n",
    )
    assert lines(src, "N012") == []


# --- uniforms ShaderToy does not set -------------------------------------------------------


def test_a_uniform_shadertoy_does_not_set_is_zero() -> None:
    src = "uniform int u_count;\nuniform float iTime;\n" + main(
        """
    vec4 sum = vec4(0.0);
    for (int i = 1; i <= u_count; i++) sum += vec4(uv, 0.0, 1.0);
    fragColor = sum / float(u_count) + vec4(1.0 / (iTime + 1.0));"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "sum / float(u_count)")
    assert "never sets `uniform u_count` (line 1)" in finding.message
    assert "(0/0: NaN)" in finding.message


# --- half-spaces ----------------------------------------------------------------------------


def test_max_zero_as_a_divisor_is_zero_for_every_negative_value() -> None:
    src = main(
        """
    vec3 rd = normalize(vec3(uv - 0.5, -1.0));
    float a = rd.x / max(0.0, rd.y);
    float b = rd.x / max(1e-3, rd.y);
    float c = uv.x / max(0.0, length(uv) + 0.5);
    fragColor = vec4(a, b, c, 1.0);"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "float a")
    assert "exactly 0 for every rd.y <= 0" in finding.message


# --- where the infinity or NaN goes (lint/analysis/moments/escape.py) -------------------------

# A swept-disk test in the style of a game buffer: at the first frame the velocity step is 0,
# so `a` is 0 and t is +-inf (or NaN where the numerator is 0).
PLANE = """
float iPlane(vec2 ro, vec2 rd, vec3 pla) {
    float a = dot(rd, pla.xy);
    float t = (1.0 - pla.z - dot(ro, pla.xy)) / a;
    if (t >= 1.0) t = -1.0;
    return t;
}
"""


def test_a_quotient_only_compared_is_not_reported() -> None:
    # +inf is cut inside iPlane, -inf and NaN fail `t1 > 0.0`: nothing non-finite is stored
    src = main(
        """
    float t = 1000.0;
    float t1 = iPlane(uv, vec2(iTimeDelta), vec3(-1.0, 0.0, 1.0));
    if (t1 > 0.0 && t1 < t) { t = t1; }
    fragColor = vec4(t);""",
        PLANE,
    )
    assert lines(src) == []


def test_a_quotient_that_passes_a_comparison_unguarded_is_reported() -> None:
    # without the `t1 > 0.0` test, -inf (and NaN) reach the colour
    src = main(
        """
    float t1 = iPlane(uv, vec2(iTimeDelta), vec3(-1.0, 0.0, 1.0));
    fragColor = vec4(t1);""",
        PLANE,
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "float t1 = iPlane")
    assert "reaches fragColor (the pixel's colour)" in finding.message


def test_an_infinity_clamped_by_max_of_its_sign_is_not_reported() -> None:
    # -1 / +0 is -inf, and max(0.0, -inf) is 0
    src = main("fragColor = vec4(max(0.0, -1.0 / iTime));")
    assert lines(src) == []
    # min(1.0, +inf) is 1, and smoothstep and clamp bound both infinities
    src = main("fragColor = vec4(min(1.0, (uv.x + 1.0) / iTime));")
    assert lines(src) == []
    src = main("fragColor = vec4(smoothstep(0.0, 1.0, 0.5 + 2.0 / iTime));")
    assert lines(src) == []


def test_an_infinity_of_the_other_sign_passes_max() -> None:
    src = main("fragColor = vec4(max(0.0, 1.0 / iTime));")
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert "an infinity reaches fragColor" in finding.message


def test_0_over_0_is_nan_and_max_does_not_absorb_it() -> None:
    src = main("fragColor = vec4(max(0.0, sin(iTime) / iTime));")
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert "(0/0: NaN)" in finding.message and "NaN reaches max(), whose result" in finding.message
    # comparisons do: NaN > 0.0 is false
    src = main("fragColor = vec4(sin(iTime) / iTime > 0.0 ? 1.0 : 0.0);")
    assert lines(src) == []


def test_an_infinity_stored_then_multiplied_into_the_colour_is_reported() -> None:
    src = main(
        """
    float k = 1.0 / iTime;
    vec3 col = vec3(0.5, 0.6, 0.7);
    col *= k;
    fragColor = vec4(col, 1.0);"""
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert finding.line == line_of(src, "1.0 / iTime")
    assert "at the first frame (iTime = 0), and an infinity reaches fragColor" in finding.message


def test_an_infinity_overwritten_before_use_is_not_reported() -> None:
    src = main(
        """
    float k = 1.0 / iTime;
    k = 2.0;
    fragColor = vec4(k);"""
    )
    assert lines(src) == []


REP = """
vec3 opRep(vec3 p, vec3 c) {
    return mod(p, c) - 0.5 * c;
}
"""


def test_a_nan_component_nobody_reads_is_not_reported() -> None:
    # mod by c.z = 0 makes only .z NaN
    src = main(
        """
    vec3 q = opRep(vec3(uv, 1.0), vec3(4.0, 4.0, 0.0));
    fragColor = vec4(length(q.xy));""",
        REP,
    )
    assert lines(src) == []
    src = main(
        """
    vec3 q = opRep(vec3(uv, 1.0), vec3(4.0, 4.0, 0.0));
    fragColor = vec4(length(q));""",
        REP,
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert "makes opRep() take mod by c" in finding.message
    assert "NaN reaches fragColor" in finding.message


def test_a_non_finite_argument_is_followed_into_the_callee() -> None:
    helpers = """
float inside(float x) { return x < 0.5 ? 1.0 : 0.0; }
float scale(float x) { return 2.0 * x; }
"""
    src = main("fragColor = vec4(inside(1.0 / iTime));", helpers)
    assert lines(src) == []
    src = main("fragColor = vec4(scale(1.0 / iTime));", helpers)
    assert lines(src) == [line_of(src, "1.0 / iTime")]


def test_a_non_finite_value_written_to_a_global_escapes() -> None:
    src = "float speed;\nvoid step_it() { speed = 1.0 / iTimeDelta; }\n" + main(
        "step_it();\n    fragColor = vec4(0.5);"
    )
    (finding,) = [f for f in lint(src) if f.code == "N011"]
    assert "reaches the global speed" in finding.message


def test_a_value_carried_to_the_next_iteration_is_followed() -> None:
    # b reads the infinity only on the second pass of the body
    src = main(
        """
    float a = 0.0, b = 0.0;
    for (int i = 0; i < 4; i++) { b = a; a = 1.0 / iTime; }
    fragColor = vec4(b);"""
    )
    assert lines(src) == [line_of(src, "1.0 / iTime")]
    src = main(
        """
    float a = 0.0, b = 0.0;
    for (int i = 0; i < 4; i++) { b = a; a = 1.0 / iTime; }
    fragColor = vec4(b > 1.0 ? 1.0 : 0.0);"""
    )
    assert lines(src) == []
