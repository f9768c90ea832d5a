"""Rules for arguments in the wrong order and copy-paste slips (N010, C108, C109), conditions
that are always false (N013) and uniforms ShaderToy never sets (P008): each reports the slip
and leaves alone the nearby code written so on purpose."""

from __future__ import annotations

from glint.lint.finding import Finding
from glint.lint.options import Options
from glint.lint.runner import lint_source


def lint(src: str, code: str, target: str = "shadertoy") -> list[Finding]:
    options = Options(select=[code], glslang=False, target=target)
    return [f for f in lint_source(src, "t.glsl", options) if f.code == code]


def main(body: str, helpers: str = "") -> str:
    return (
        helpers
        + "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        + "    vec2 uv = fragCoord / iResolution.xy;\n"
        + body
        + "\n    fragColor = vec4(uv, 0.0, 1.0);\n}\n"
    )


def lines(found: list[Finding]) -> list[int]:
    return sorted(f.line for f in found)


# --- N010 value-passed-as-bound ---------------------------------------------------------------


def test_n010_reports_the_value_passed_as_a_bound() -> None:
    src = main(
        "    float z = 100.0 * uv.x;\n"  # line 4
        "    float w = clamp(0.2, 0.5, 1.0 - z * 0.01);\n"  # 5: value last
        "    float v = clamp(0.0, uv.y * 3.0, 2.0);\n"  # 6: value as the lower bound
        "    float m = smoothstep(length(uv), 0.0, 0.01);\n"  # 7: value as edge0
        "    float n = smoothstep(0.0, uv.x, 0.5);\n"  # 8: value as edge1
    )
    found = lint(src, "N010")
    assert lines(found) == [5, 6, 7, 8]
    assert "write clamp(1.0 - z * 0.01, 0.2, 0.5)" in found[0].message
    assert "write clamp(uv.y * 3.0, 0.0, 2.0)" in found[1].message
    assert "write smoothstep(0.0, 0.01, length(uv))" in found[2].message


def test_n010_leaves_the_usual_orders_and_the_reversed_edge_idiom() -> None:
    src = main(
        "    float a = clamp(uv.x, 0.0, 1.0);\n"
        "    float b = smoothstep(0.01, 0.0, length(uv));\n"  # reversed edges on purpose
        "    float c = clamp(0.5, uv.x, uv.y + 1.0);\n"  # both bounds vary: a relation
        "    float d = clamp(0.5, 0.0, 1.0);\n"  # all constant: folded, whatever it means
        "    float e = clamp(0.0, 1.0, sin(iTime));\n"  # inverted over the ranges: N008's
    )
    assert lint(src, "N010") == []
    assert lines(lint(src, "N008")) == [8]


def test_n010_counts_a_local_with_one_constant_value_as_constant() -> None:
    src = main("    const float lo = 0.1;\n    float k = 0.3;\n    float w = clamp(k, lo, uv.x);\n")
    assert lines(lint(src, "N010")) == [6]


# --- P008 uniform-not-provided ----------------------------------------------------------------

UNIFORMS = """uniform bool u_shadows;
uniform float u_scale, u_unused;
uniform sampler2D u_tex;
uniform vec3 u_lights[2];
"""


def test_p008_reports_uniforms_shadertoy_never_sets_that_are_read() -> None:
    src = main(
        "    vec3 col = vec3(uv * u_scale, 0.0) + u_lights[0];\n"
        "    if (u_shadows) col *= 0.5;\n"
        "    col += texture(u_tex, uv).rgb;\n",
        UNIFORMS,
    )
    found = lint(src, "P008")
    assert lines(found) == [1, 2, 4]  # not u_unused (never read), not the sampler
    assert "uniform bool u_shadows" in found[0].message
    message = found[0].message
    assert "always false, so the branch of `if (u_shadows)` at line 9 never runs" in message
    assert "always 0.0" in found[1].message
    assert "vec3[]" in found[2].message


def test_p008_leaves_other_targets_and_shadertoys_own_inputs() -> None:
    src = main("    if (u_shadows) uv *= 0.5;\n", "uniform bool u_shadows;\n")
    assert lint(src, "P008", target="webgl2") == []
    own = main("    uv *= iTime;\n", "uniform float iTime;\n")
    assert lint(own, "P008") == []


def test_p008_a_local_of_the_same_name_hides_the_uniform() -> None:
    """`float time = iTime;` in mainImage shadows `uniform float time;`: its reads there are
    of the local, so the uniform is not read at all."""
    helpers = "uniform float time;\nuniform vec2 resolution;\n"
    src = main(
        "    float time = iTime * 0.5;\n    vec2 resolution = iResolution.xy;\n"
        "    uv += sin(time) / resolution;\n",
        helpers,
    )
    assert lint(src, "P008") == []
    read = main("    float t = time;\n    uv += sin(t) / resolution;\n", helpers)
    assert lines(lint(read, "P008")) == [1, 2]


def test_p008_a_fallback_for_the_unset_zero_is_left_alone() -> None:
    """`u == 0.0 ? DEFAULT : u` replaces the zero the shader gets; a mode switch whose zero
    picks a branch, an else-if chain on the mode, or a value also read outside its guard is
    still reported."""
    src = main(
        "    float b = (u_bright == 0.0) ? 1.2 : u_bright;\n"  # line 7: a fallback
        "    float g = u_gain != 0.0 ? u_gain : 1.0;\n"  # 8: a fallback, the other way round
        "    if (u_mode == 0) uv *= 2.0; else if (u_mode == 1) uv *= 3.0;\n"  # 9: a mode
        "    float h = u_half == 0.0 ? 0.5 : u_half;\n    uv *= b * g * h * u_half;\n",
        "uniform float u_bright, u_gain, u_half;\nuniform int u_mode;\n",
    )
    found = {f.message.split()[2] for f in lint(src, "P008")}
    assert found == {"u_mode", "u_half"}


def test_p008_says_which_branch_or_loop_the_zero_kills() -> None:
    src = main(
        "    if (!u_fast) uv *= 2.0;\n"  # line 6: always true, no else: kills nothing
        "    if (u_fast) uv *= 0.5;\n"  # 7: never runs: the one to name
        "    if (u_mode == 0) uv.x += 1.0; else uv.y += 1.0;\n"  # 8: the else never runs
        "    for (int i = 0; i < u_count; i++) uv *= 0.9;\n"  # 9: never runs
        "    for (int i = 0; i <= u_max; i++) uv *= 0.9;\n"  # 10: runs: no claim of 'always'
        "    float s = u_on && uv.x > 0.5 ? 1.0 : 2.0;\n",  # 11: the ?: takes its second value
        "uniform bool u_fast, u_on;\nuniform int u_mode, u_count, u_max;\n",
    )
    found = {f.message.split()[2]: f.message for f in lint(src, "P008")}
    assert "the branch of `if (u_fast)` at line 7 never runs" in found["u_fast"]
    assert "the else branch of `if (u_mode == 0)` (line 8) never runs" in found["u_mode"]
    assert "the loop at line 9 never runs: `i < u_count` is false" in found["u_count"]
    assert "the test `i <= u_max` at line 10 always reads it as 0" in found["u_max"]
    assert "always takes its second value" in found["u_on"]


def test_p008_takes_a_for_loops_condition_not_its_update() -> None:
    src = main(
        "    for (float t = 0.0; ; t += u_step) { if (t > 1.0) break; uv *= 0.9; }\n"  # line 7
        "    for (; u_on;) { uv *= 0.9; break; }\n"  # 8: the lone middle part is the condition
        "    for (int i = 0; ; i += u_inc) { if (i > 4) break; }\n",  # 9: the update again
        "uniform float u_step;\nuniform bool u_on;\nuniform int u_inc;\n",
    )
    found = {f.message.split()[2]: f.message for f in lint(src, "P008")}
    assert "always 0.0 wherever it is read (first at line 7)" in found["u_step"]
    assert "test" not in found["u_step"]  # `t += u_step` is no test of the loop
    assert "the loop at line 8 never runs: `u_on` is false from the start" in found["u_on"]
    assert "wherever it is read (first at line 9)" in found["u_inc"]


def test_p008_names_a_division_or_product_the_zero_spoils() -> None:
    src = main(
        "    float k = 2.0 * u_height;\n"  # line 5: a scale by a literal names nothing
        "    uv *= k + u_width;\n"
        "    uv = uv / u_zoom;\n"  # 7: divides by zero
        "    uv += uv.x * u_speed;\n",  # 8: always zero
        "uniform float u_height, u_width, u_zoom, u_speed;\n",
    )
    found = {f.message.split()[2]: f.message for f in lint(src, "P008")}
    assert "`uv / u_zoom` at line 7 divides by zero" in found["u_zoom"]
    assert "`uv.x * u_speed` at line 8 is always zero" in found["u_speed"]
    assert "always 0.0 wherever it is read (first at line 5)" in found["u_height"]
    assert "always 0.0 wherever it is read (first at line 6)" in found["u_width"]


# --- C108 unused-twin -------------------------------------------------------------------------

CHECKERS = "float checkers(vec2 p, vec2 dx, vec2 dy) { return p.x + dx.x + dy.y; }\n"


def test_c108_reports_the_call_that_passes_the_used_twin_twice() -> None:
    src = main(
        "    vec2 ddx_uv = dFdx(uv);\n    vec2 ddy_uv = dFdy(uv);\n"
        "    float c = checkers(uv, ddy_uv, ddy_uv);\n    uv *= c;\n",
        CHECKERS,
    )
    found = lint(src, "C108")
    assert lines(found) == [7]
    assert "`ddy_uv` is passed twice" in found[0].message
    assert "`ddx_uv`" in found[0].message


def test_c108_reports_the_live_value_read_beside_saved_copies() -> None:
    helpers = "float glow = 0.0, glow2 = 0.0, glow3 = 0.0;\n"
    src = main(
        "    float glowSave = glow;\n    float glow2Save = glow2;\n    float glow3Save = glow3;\n"
        "    vec3 col = vec3(0.0);\n"
        "    col += vec3(0.3) * glowSave;\n"
        "    col += vec3(0.9) * glow2;\n"  # line 8: glow2Save was meant
        "    col += vec3(0.2) * glow3Save;\n"
        "    uv += col.xy;\n",
        helpers,
    )
    found = lint(src, "C108")
    assert lines(found) == [10]
    assert "`glow2Save`" in found[0].message


def test_c108_reports_an_unused_twin_at_its_declaration() -> None:
    src = main(
        "    float t = sin(uv.x) + 13.0;\n    float t2 = sin(uv.y) + 13.0;\n    uv.y += t;\n"
    )
    found = lint(src, "C108")
    assert lines(found) == [5]
    assert "`t2` is computed like its twin `t`" in found[0].message


def test_c108_leaves_plain_unused_values_and_families() -> None:
    src = main(
        "    float unused = cos(uv.x);\n"  # no twin
        "    float f0 = sin(uv.x), f1 = sin(uv.y), f2 = sin(uv.x * 2.0);\n"  # f1 one of many
        "    float a = uv.x * 2.0;\n    float a2 = cos(iTime) * length(uv) + 1.0;\n"  # unlike
        "    uv += f0 + f2 + a;\n"
    )
    assert lint(src, "C108") == []


# --- C109 inconsistent-twin-line --------------------------------------------------------------


def test_c109_reports_the_copy_that_reads_one_component_twice() -> None:
    src = main(
        "    vec4 p1 = vec4(0.5, 4.0, 0.1, 0.2);\n    vec4 p2 = vec4(0.3, 9.0, 0.2, 0.1);\n"
        "    float b1 = p1.x * texture(iChannel0, uv * p1.y).x;\n"
        "    float b2 = p2.x * texture(iChannel0, uv * p2.x).x;\n"  # line 5
        "    uv += b1 + b2;\n"
    )
    found = lint(src, "C109")
    assert lines(found) == [7]
    assert "`p2.y` was probably meant" in found[0].message


def test_c109_leaves_consistent_copies_and_permutations() -> None:
    src = main(
        "    vec3 a1 = vec3(uv, 1.0), a2 = vec3(uv.yx, 2.0), b = vec3(1.0), c;\n"
        "    float b1 = a1.x * texture(iChannel0, uv * a1.y).x;\n"
        "    float b2 = a2.x * texture(iChannel0, uv * a2.y).x;\n"
        "    c.x = a1.y * a2.z - a1.z * a2.y;\n"  # a cross product: a rotation of letters
        "    c.y = a1.z * a2.x - a1.x * a2.z;\n"
        "    float s1 = b.x * b.y;\n"  # not renamed to a twin: b is b
        "    float s2 = b.x * b.x;\n"
        "    uv += b1 + b2 + c.xy + s1 + s2;\n"
    )
    assert lint(src, "C109") == []


# --- N013 condition-always-same ---------------------------------------------------------------


def test_n013_reports_a_guard_the_code_before_it_ruled_out() -> None:
    src = main(
        "    float t = length(uv) - 0.5;\n"
        "    if (t < 0.0) t = 600.0;\n"
        "    if (t < 0.0) uv = vec2(0.0);\n"  # line 6
        "    float d = uv.x - 0.3;\n"
        "    if (abs(d) < 0.0 || d > 2.0) uv.y = 1.0;\n"  # line 6
        "    if (t > 500.0) uv.x += 1.0;\n"
        "    else if (t > 800.0) uv.x += 2.0;\n"  # line 8: the first test takes these
        "    else if (t > 1000.0) uv.x += 3.0;\n"  # one finding for the chain
    )
    found = lint(src, "N013")
    assert lines(found) == [6, 8, 10]
    assert "`t < 0.0` is always false" in found[0].message
    assert "[0, inf)" in found[1].message


def test_n013_leaves_conditions_constant_on_purpose() -> None:
    helpers = (
        "#define SHADOWS 0\n#define PICK(a, b) ((a).x < (b).x ? (a) : (b))\n"
        "float f(float x) { if (x < 0.0) return 0.0; return sqrt(x); }\n"
    )
    src = main(
        "    if (SHADOWS == 1) uv *= 0.5;\n"  # a switch written with a macro
        "    if (false) uv *= 0.5;\n"
        "    const float k = 2.0;\n    if (k > 3.0) uv *= 0.5;\n"  # constant on purpose
        "    uv.x += f(abs(uv.x));\n"  # the helper's defensive test of its parameter
        "    float t = length(uv);\n    if (t >= 0.0) uv *= 2.0;\n"  # always true: harmless
        "    if (iTime < -1.0) uv *= 2.0;\n"  # a test of ShaderToy's input
        "    for (int i = 0; i < 3; i++) { int j = i; if (j >= 3) j -= 3; uv.x += float(j); }\n"
        "    float s = length(uv) - 1.0;\n"
        "    if (s < 0.0) return;\n    if (s < 0.0) uv *= 3.0;\n"  # re-check after an exit
        "    vec2 m = PICK(vec2(-length(uv), 0.0), vec2(1.0));\n    uv += m;\n"  # a macro's body
        "    if (uv.x < uv.y) uv *= 0.5;\n"
        "    float q = length(uv);\n    if (q < 0.0) uv *= 0.5;\n",  # the one finding: line 23
        helpers,
    )
    assert lines(lint(src, "N013")) == [23]
