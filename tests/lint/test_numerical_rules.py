"""Numerical-hazard rules N001-N009: a positive and a negative case each, the messages, the
unsafe fixes (and that the fixed shader still compiles), and the valid corpus and catalog
snippets staying clean."""

from __future__ import annotations

from pathlib import Path

import pytest

from glint.compiler.target.glslang import validate
from glint.lint.finding import Finding
from glint.lint.options import Options
from glint.lint.rules import all_rules, rule_doc
from glint.lint.runner import lint_source, lint_text

ROOT = Path(__file__).resolve().parents[2]
# The range rules. The moment rules (N011, N012; tests/lint/test_moments.py) would report the
# header's L, which is normalize(vec3(0.0)) at the first frame, where sin(iTime) is 0.
FAST = Options(select=["N"], ignore=["N011", "N012"], glslang=False)

HEADER = """
vec3 N = normalize(vec3(fragCoord, 1.0) - 0.5);
vec3 L = normalize(vec3(1.0, 2.0, 3.0) * sin(iTime));
vec3 V = normalize(vec3(fragCoord.yx, 2.0) - 3.0);
vec3 H = normalize(vec3(fragCoord, 5.0) + 1.0);
"""


def shader(body: str, helpers: str = "", header: bool = True) -> str:
    """A complete ShaderToy shader with `body` inside mainImage."""
    head = HEADER if header else ""
    return (
        helpers
        + "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        + head
        + body
        + "\n    fragColor = vec4(0.0, 0.0, 0.0, 1.0);\n}\n"
    )


def lint(src: str) -> list[Finding]:
    return lint_source(src, "t.glsl", FAST)


def codes(src: str, code: str | None = None) -> list[str]:
    found = [f.code for f in lint(src)]
    return [c for c in found if code is None or c == code]


def only(src: str, code: str) -> Finding:
    found = [f for f in lint(src) if f.code == code]
    assert len(found) == 1, found
    return found[0]


def fixed(src: str) -> str:
    return lint_text(src, "t.glsl", FAST, fix=True, unsafe_fixes=True).text


def compiles(src: str) -> bool:
    return not [d for d in validate(src, "t.glsl") if d.severity == "error"]


# --- the registry -----------------------------------------------------------------------------


def test_rules_are_registered_with_docs_names_and_fixability() -> None:
    rules = {c: r for c, r in all_rules().items() if c.startswith("N")}
    assert {f"N00{i}" for i in range(1, 10)} <= set(rules)  # and the later ones (N010, ...)
    for rule in rules.values():
        doc = rule_doc(rule)
        assert doc["summary"] and doc["why"] and doc["example"] and doc["fix"]
        assert rule.category == "numerical" and rule.name == rule.name.lower()
    assert rules["N001"].fixable == "unsafe" and rules["N005"].fixable == "unsafe"


# --- N001 pow -------------------------------------------------------------------------------


def test_pow_of_an_unclamped_dot_product() -> None:
    f = only(shader("float s = pow(dot(N, H), 32.0);"), "N001")
    assert f.message == (
        "pow base dot(N, H) is negative where the vectors of an unclamped dot product with a "
        "direction face away: pow is undefined there (NaN on most GPUs); clamp it: "
        "pow(max(dot(N, H), 0.0), ...), or use abs(dot(N, H)) for a curve symmetric about 0, "
        "or write a square as a product"
    )
    assert f.severity == "warning" and f.fix is not None and f.fix.applicability == "unsafe"


def test_pow_of_a_clamped_dot_product_is_clean() -> None:
    assert codes(shader("float s = pow(max(dot(N, H), 0.0), 32.0);"), "N001") == []
    assert codes(shader("float s = pow(clamp(dot(N, H), 0.0, 1.0), 32.0);"), "N001") == []
    assert codes(shader("float d = dot(N, H);\nif (d > 0.0) { float s = pow(d, 8.0); }")) == []


def test_pow_through_a_variable_and_in_a_helper_with_unknown_vectors() -> None:
    assert codes(shader("float nh = dot(N, H);\nfloat s = pow(nh, 16.0);"), "N001") == ["N001"]
    helper = "float spec(vec3 n, vec3 h, float e) { return pow(dot(n, h), e); }\n"
    # never called: nothing is known of n and h, so no input is named (N020, opt-in)
    assert codes(shader("", helper, header=False), "N001") == []
    f = only(shader("", helper, header=False), "N020")
    assert "unclamped dot product" in f.message


def test_pow_base_whose_whole_range_is_at_most_zero() -> None:
    f = only(shader("float t = fragCoord.x;\nfloat s = pow(clamp(t, 1., 3.) - 3., 2.);"), "N001")
    assert "is never above 0 (range [-2, 0])" in f.message


def test_pow_base_negative_at_the_first_frame_and_through_sin() -> None:
    f = only(shader("float s = pow(iTime * 2.0 - 1.0, 2.0);"), "N001")
    assert "at the first frame, iTime = 0 (down to -1)" in f.message
    f = only(shader("float s = pow(sin(iTime * 4.0), 7.0);"), "N001")
    assert "where sin or cos of an unbounded argument is negative" in f.message
    assert codes(shader("float s = pow(0.5 + 0.5 * sin(iTime), 7.0);"), "N001") == []
    assert codes(shader("float s = pow(iTime + 1.0, 2.0);")) == []


def test_pow_base_negative_at_the_bottom_left_pixel() -> None:
    f = only(shader("float s = pow(fragCoord.y / iResolution.y - 0.5, 2.0);"), "N001")
    assert "at the bottom-left pixel, fragCoord = (0.5, 0.5) (down to" in f.message
    assert "pow(max(fragCoord.y / iResolution.y - 0.5, 0.0), ...)" in f.message
    assert "abs(fragCoord.y / iResolution.y - 0.5)" in f.message
    # 0.5 / height is at most 1/32 there: above 0, and above 0.01 (no witness below 0)
    assert codes(shader("float s = pow(fragCoord.y / iResolution.y, 2.0);"), "N001") == []
    assert codes(shader("float s = pow(fragCoord.y / iResolution.y - 0.01, 2.0);"), "N001") == []
    # mainImage's pixel coordinate under another name, and a component written on its own
    src = (
        "void mainImage(out vec4 O, in vec2 U) {\n"
        "    vec2 p = U / iResolution.xy - 0.5;\n    p.x *= iResolution.x / iResolution.y;\n"
        "    O = vec4(pow(p.x, 3.0));\n}\n"
    )
    assert "at the bottom-left pixel" in only(src, "N001").message


def test_pow_of_a_view_ray_component_before_the_camera_turns_it() -> None:
    uv = "vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
    f = only(shader(uv + "vec3 rd = normalize(vec3(uv, 1.5));\nfloat c = pow(rd.y, 0.5);"), "N001")
    assert "rd.y is negative for view rays towards the bottom-left of the screen:" in f.message
    assert "(down to" not in f.message  # only its sign is known
    # turning x and z about the vertical keeps y
    turned = "rd.xz *= mat2(cos(iTime), sin(iTime), -sin(iTime), cos(iTime));\n"
    src = shader(
        uv + "vec3 rd = normalize(vec3(uv, 1.5));\n" + turned + "float c = pow(rd.y, 0.5);"
    )
    assert codes(src, "N001") == ["N001"]
    # a camera matrix: rd.y in the world depends on where the camera looks, so no witness
    cam = "mat3 ca = mat3(normalize(vec3(1.0, 0.0, sin(iTime))), vec3(0, 1, 0), vec3(0, 0, 1));\n"
    src = shader(uv + cam + "vec3 rd = ca * normalize(vec3(uv, 1.5));\nfloat c = pow(rd.y, 0.5);")
    assert codes(src, "N001") == []
    # z is 1.5 before normalizing: positive everywhere
    src = shader(uv + "vec3 rd = normalize(vec3(uv, 1.5));\nfloat c = pow(rd.z, 0.5);")
    assert codes(src, "N001") == []
    # a sky term guarded by the ray pointing up is clean
    src = shader(
        uv + "vec3 rd = normalize(vec3(uv, 1.5));\nif (rd.y > 0.0) { float c = pow(rd.y, 0.5); }"
    )
    assert codes(src, "N001") == []


def test_a_positive_witness_over_a_resolution_is_bounded_by_the_smallest_canvas() -> None:
    # at the first frame (iTime + 1) / iResolution.x is 1 / width, at most 1/16: above 0.05
    assert codes(shader("float s = pow((iTime + 1.0) / iResolution.x - 0.05, 2.0);"), "N001") == []
    f = only(shader("float s = pow((iTime + 1.0) / iResolution.x - 0.1, 2.0);"), "N001")
    assert "at the first frame, iTime = 0 (down to -0.0375)" in f.message


def test_pow_of_a_colour_channel_from_a_function_and_a_product() -> None:
    helper = (
        "vec3 material(float k) {\n"
        "    return k > 0.5 ? vec3(1.0, sin(iTime), 0.5) : vec3(0.0, 0.5, 0.5);\n}\n"
    )
    body = (
        "vec3 col = material(fragCoord.x) * max(0.2, fragCoord.y);\n"
        "col = pow(col, vec3(0.4545));\nfragColor = vec4(col, 1.0);"
    )
    f = only(shader(body, helper, header=False), "N001")
    assert "negative in y" in f.message
    # a light that is never negative, times the same channel clamped, is clean
    clean = body.replace("material(fragCoord.x)", "max(material(fragCoord.x), 0.0)")
    assert codes(shader(clean, helper, header=False), "N001") == []


def test_pow_of_one_plus_a_dot_of_unit_vectors_is_clean() -> None:
    assert codes(shader("float f = pow(1.0 + dot(N, -V), 5.0);"), "N001") == []
    assert codes(shader("float f = pow(1.0 + dot(N, -V), 5.0);"), "N020") == []


def test_pow_base_narrowed_by_a_condition_has_no_witness() -> None:
    assert codes(shader("float s = sin(iTime);\nif (s > 0.0) { s = pow(s, 2.0); }")) == []
    assert codes(shader("float t = iTime - 1.0;\nif (t >= 0.0) { t = pow(t, 2.0); }")) == []


def test_pow_of_an_unknown_value_is_not_reported() -> None:
    helper = "vec3 gamma(vec3 c) { return pow(c, vec3(1.0 / 2.2)); }\n"
    assert codes(shader("", helper, header=False)) == []


def test_pow_fix_inserts_max_and_still_compiles() -> None:
    src = shader("float s = pow(dot(N, H), 32.0);\nfragColor = vec4(s);")
    out = fixed(src)
    assert "pow(max(dot(N, H), 0.0), 32.0)" in out
    assert codes(out, "N001") == []
    assert compiles(out)


def test_no_fix_on_a_macro_line() -> None:
    src = "#define SPEC(a, b) pow(dot(a, b), 8.0)\n" + shader("float s = SPEC(N, H);")
    f = only(src, "N001")
    assert f.fix is None


# --- N002 sqrt / log ------------------------------------------------------------------------


def test_sqrt_of_a_value_that_may_be_negative() -> None:
    f = only(shader("float s = sqrt(sin(iTime));"), "N002")
    assert "sqrt of sin(iTime), which may be negative (range [-1, 1])" in f.message
    out = fixed(shader("float s = sqrt(sin(iTime));\nfragColor = vec4(s);"))
    assert "sqrt(max(sin(iTime), 0.0))" in out and compiles(out)


def test_log_of_a_value_that_may_be_zero() -> None:
    f = only(shader("float l = log(max(sin(iTime), 0.0));"), "N002")
    assert "log of max(sin(iTime), 0.0), which may be zero or negative" in f.message
    assert f.fix is not None and "1e-6" in f.fix.edits[0].content


def test_sqrt_and_log_of_safe_values_are_clean() -> None:
    body = """
    float a = sqrt(max(sin(iTime), 0.0));
    float b = sqrt(dot(N, N));
    float c = log(1.0 + iTime);
    float d = log2(exp(sin(iTime)));
    float r2 = dot(fragCoord, fragCoord);
    if (r2 > 1.0) return;
    float e = sqrt(1.0 - r2);
    """
    assert codes(shader(body)) == []


def test_sqrt_of_one_minus_an_unknown_square_is_not_reported() -> None:
    helper = "float sinOf(float c) { return sqrt(1.0 - c * c); }\n"
    assert codes(shader("", helper, header=False)) == []


# --- N003 acos / asin -------------------------------------------------------------------------


def test_acos_of_an_unclamped_dot_of_unit_vectors() -> None:
    f = only(shader("float a = acos(dot(N, L));"), "N003")
    assert "unclamped dot product" in f.message and "rounds past" in f.message
    out = fixed(shader("float a = acos(dot(N, L));\nfragColor = vec4(a);"))
    assert "acos(clamp(dot(N, L), -1.0, 1.0))" in out and compiles(out)


def test_asin_of_a_value_beyond_one() -> None:
    f = only(shader("float a = asin(sin(iTime) * 1.5);"), "N003")
    assert "range [-1.5, 1.5]" in f.message


def test_acos_of_a_clamped_value_is_clean() -> None:
    assert codes(shader("float a = acos(clamp(dot(N, L), -1.0, 1.0));")) == []
    assert codes(shader("float a = acos(0.5 * sin(iTime));")) == []


# --- N004 tan -------------------------------------------------------------------------------


def test_tan_reaching_a_pole() -> None:
    assert codes(shader("float k = tan(iTime);")) == ["N004"]
    assert codes(shader("float k = tan(sin(iTime) * 2.0);")) == ["N004"]


def test_tan_away_from_poles_or_unknown_is_clean() -> None:
    assert codes(shader("float k = tan(sin(iTime));")) == []  # |x| <= 1 < pi/2
    assert codes(shader("float k = tan(radians(45.0));")) == []
    assert codes(shader("", "float f(float a) { return tan(a); }\n", header=False)) == []


# --- N005 division --------------------------------------------------------------------------


def test_division_by_a_dot_product_or_length() -> None:
    f = only(shader("float a = 1.0 / dot(N, L);"), "N005")
    assert "division by dot(N, L), which may be 0 (range [-1, 1])" in f.message
    assert f.fix is None  # a floor would flip the sign of negative divisors: no fix
    f = only(shader("vec2 d = fragCoord / length(fragCoord);"), "N005")
    assert "add an epsilon: max(length(fragCoord), 1e-4)" in f.message
    assert codes(shader("float k = 2.0;\nk /= max(dot(N, L), 0.0);"), "N005") == ["N005"]


def test_division_fix_inserts_an_epsilon_and_compiles() -> None:
    src = shader("vec2 d = fragCoord - 0.5 * iResolution.xy;\nfloat a = 1.0 / dot(d, d);\n"
                 "fragColor = vec4(a);")  # fmt: skip
    out = fixed(src)
    assert "1.0 / max(dot(d, d), 1e-4)" in out and codes(out) == [] and compiles(out)


def test_division_by_safe_values_is_clean() -> None:
    body = """
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float a = 1.0 / max(dot(N, L), 1e-4);
    float b = 1.0 / (abs(dot(N, V)) + 1e-5);
    float c = 1.0 / (1.0 + dot(uv, uv));
    float d = 0.5 / (2.0 + sin(iTime));
    """
    assert codes(shader(body)) == []


def test_division_by_products_widened_by_interval_arithmetic_is_clean() -> None:
    # GGX: f = NoH^2 (a2 - 1) + 1 >= a2 > 0, though intervals only see [0, inf)
    helper = """
    float D(float NoH, float a) {
        float a2 = a * a;
        float f = (NoH * a2 - NoH) * NoH + 1.0;
        return a2 / (3.14159 * f * f);
    }
    """
    body = "float n = clamp(dot(N, H), 0.0, 1.0);\nfloat d = D(n, 0.5);"
    assert codes(shader(body, helper)) == []


VISIBILITY = """
float V_SmithGGXCorrelated(float NoV, float NoL, float a) {
    float a2 = a * a;
    return 0.5 / (NoL * sqrt(NoV*NoV*(1.0-a2)+a2) + NoV * sqrt(NoL*NoL*(1.0-a2)+a2));
}
float G1(float NoV, float k) { return NoV / (NoV * (1.0 - k) + k); }
float V_Kelemen(float NoV, float NoL) { return 0.25 / (NoV * NoL); }
vec3 shade(vec3 n, vec3 v, vec3 l, float r) {
    float NoV = NOV;
    float NoL = NOL;
    float a = r * r;
    float k = (r + 1.0) * (r + 1.0) / 8.0;
    return vec3(V_SmithGGXCorrelated(NoV, NoL, a) * G1(NoV, k) * V_Kelemen(NoV, NoL));
}
"""
SHADE = "fragColor = vec4(shade(N, V, L, clamp(sin(iTime), 0.05, 1.0)), 1.0);"


def test_division_by_a_cosine_passed_to_a_visibility_function() -> None:
    # an unclamped N·V reaches the denominators through a parameter, two calls deep
    src = shader(
        SHADE, VISIBILITY.replace("NOV", "dot(n, v)").replace("NOL", "max(dot(n, l), 1e-4)")
    )
    found = [f for f in lint(src) if f.code == "N005"]
    assert [f.line for f in found] == [4, 6, 7]
    for f in found:
        assert "unclamped dot product passed as an argument" in f.message, f.message


def test_division_by_a_clamped_cosine_passed_to_a_visibility_function_is_clean() -> None:
    src = shader(SHADE, VISIBILITY.replace("NOV", "max(dot(n, v), 1e-4)").replace(
        "NOL", "max(dot(n, l), 1e-4)"))  # fmt: skip
    assert codes(src, "N005") == []
    # NoL clamped at 0 still zeroes a product (the unlit half), not Smith's sum with NoV > 0
    src = shader(SHADE, VISIBILITY.replace("NOV", "max(dot(n, v), 1e-4)").replace(
        "NOL", "max(dot(n, l), 0.0)"))  # fmt: skip
    assert [f.line for f in lint(src) if f.code == "N005"] == [7]


def test_division_by_a_nonzero_component_or_an_unknown_range_is_clean() -> None:
    # eps.y is 0, eps.x = 4/iResolution.y is not: a picked component has its own evidence
    body = "vec2 eps = vec2(4.0 / iResolution.y, 0.0);\nfloat fx = sin(iTime) / eps.x;"
    assert codes(shader(body), "N005") == []
    # pow(2.0, x) is 1 where x is 0: no evidence of a 0 passes through it
    body = "float b = floor(iTime);\nfloat q = 1.0 / pow(2.0, b);"
    assert codes(shader(body), "N005") == []
    # nothing known of the range: no evidence (sin(...) times an unknown parameter)
    helpers = "float f(float r, float p) { float size = sin(r) * r * p; return 1.0 / size; }\n"
    assert codes(shader("", helpers), "N005") == []


def test_division_guarded_by_a_strict_comparison_is_clean() -> None:
    body = "vec2 uv = fragCoord - 0.5;\nfloat a = (uv.x > 0.0) ? acos(uv.y / length(uv)) : 0.0;"
    assert codes(shader(body), "N005") == []


def test_division_by_constant_zero() -> None:
    assert codes(shader("float z = 1.0 / 0.0;")) == ["N005"]


# --- N006 normalize ---------------------------------------------------------------------------


def test_normalize_of_a_sum_of_unit_vectors_and_of_a_cross_product() -> None:
    f = only(shader("vec3 h = normalize(L + V);"), "N006")
    assert "the sum of two unit vectors is zero when they are opposite" in f.message
    assert codes(shader("vec3 t = normalize(cross(N, L));")) == ["N006"]
    assert codes(shader("vec3 z = normalize(vec3(0.0));")) == ["N006"]


def test_normalize_of_other_vectors_is_clean() -> None:
    body = """
    vec3 a = normalize(vec3(fragCoord, 1.0));
    vec3 b = normalize(N + vec3(0.0, 2.0, 0.0));
    vec3 up = normalize(cross(N, vec3(0.0, 1.0, 0.0)));
    """
    assert codes(shader(body)) == []


def test_normalize_of_the_look_at_basis_is_clean() -> None:
    # uu = normalize(cross(ww, up)) is unit and orthogonal to ww: cross(uu, ww) is unit; a
    # rolled up axis (sin r, cos r, 0) is a chosen axis like the constant world up
    body = """
    vec3 ro = vec3(sin(iTime), 1.0, cos(iTime)) * 4.0;
    vec3 ww = normalize(vec3(0.0) - ro);
    float cr = 0.1 * sin(iTime);
    vec3 cp = vec3(sin(cr), cos(cr), 0.0);
    vec3 uu = normalize(cross(ww, cp));
    vec3 vv = normalize(cross(uu, ww));
    vec3 d = normalize(vec3(fragCoord, 1.0));
    vec3 u = cross(d, vec3(1.0, 0.0, 0.0));
    vec3 v = normalize(cross(u, d));
    """
    assert codes(shader(body), "N006") == []


def test_normalize_of_a_cross_of_vectors_not_known_orthogonal_is_reported() -> None:
    body = """
    vec3 a = normalize(vec3(fragCoord, 1.0));
    vec3 b = normalize(vec3(sin(iTime), cos(iTime), sin(2.0 * iTime)));
    vec3 c = normalize(cross(a, b));
    vec3 e = normalize(cross(c, b));
    """
    # c is orthogonal to b (unit): cross(c, b) is unit; cross(a, b) is not
    found = [f for f in lint(shader(body)) if f.code == "N006"]
    assert len(found) == 1 and "cross(a, b)" in found[0].message


# --- N007 mod / atan --------------------------------------------------------------------------


def test_mod_by_zero_and_atan_of_zero_zero_are_errors() -> None:
    f = only(shader("float m = mod(iTime, 0.0);"), "N007")
    assert f.severity == "error"
    f = only(shader("#define ZERO 0.0\nfloat a = atan(ZERO, 0.0);"), "N007")
    assert f.severity == "error" and f.message == "atan(0, 0) is undefined"


def test_atan_where_both_arguments_may_be_zero() -> None:
    f = only(shader("vec2 p = vec2(max(sin(iTime), 0.0), 0.5 * sin(iTime));\n"
                    "float a = atan(p.y, p.x);"), "N007")  # fmt: skip
    assert f.severity == "warning" and "both may be 0" in f.message


def test_mod_and_atan_with_safe_arguments_are_clean() -> None:
    body = """
    float m = mod(iTime, 2.0);
    float a = atan(sin(iTime), cos(iTime));
    float b = atan(fragCoord.y - 0.5 * iResolution.y, fragCoord.x);
    float c = atan(sin(iTime), 1.0);
    """
    assert codes(shader(body)) == []


# --- N008 clamp / N009 smoothstep -------------------------------------------------------------


def test_clamp_with_the_value_passed_last_looks_swapped() -> None:
    # clamp(0.0, 1.0, v) with v in [-1, 1]: min >= max over the whole range, so the result is
    # always v, unclamped
    f = only(shader("float v = sin(iTime);\nfloat c = clamp(0.0, 1.0, v);"), "N008")
    assert "swapped" in f.message and "clamp takes the value first" in f.message
    assert f.severity == "warning"
    assert codes(shader("float v = sin(iTime);\nfloat c = clamp(v, 0.0, 1.0);"), "N008") == []
    # bounds that overlap somewhere are no evidence
    assert codes(shader("float v = sin(iTime);\nfloat c = clamp(0.5, v, 1.0);"), "N008") == []


def test_clamp_with_bounds_inverted_over_their_ranges() -> None:
    src = shader("float lo = 2.0 + abs(sin(iTime));\nfloat c = clamp(iTime, lo, cos(iTime));")
    f = only(src, "N008")
    assert "for every value" in f.message and f.severity == "warning"


def test_clamp_with_inverted_constant_bounds() -> None:
    f = only(shader("float c = clamp(sin(iTime), 1.0, 0.0);"), "N008")
    assert f.severity == "warning" and "1.0 > 0.0" in f.message
    assert codes(shader("float c = clamp(sin(iTime), 0.0, 1.0);")) == []
    assert codes(shader("", "float f(float x, float a) { return clamp(x, a, 1.0); }\n",
                        header=False)) == []  # fmt: skip


def test_smoothstep_with_inverted_edges_and_its_fix() -> None:
    src = shader("float s = smoothstep(1.0, 0.0, sin(iTime));\nfragColor = vec4(s);")
    f = only(src, "N009")
    # the same mirrored ramp on every GPU: a portability warning, not an error
    assert f.severity == "warning" and f.fix is not None and f.fix.applicability == "safe"
    out = lint_text(src, "t.glsl", FAST, fix=True).text
    assert "(1.0 - smoothstep(0.0, 1.0, sin(iTime)))" in out and compiles(out)
    assert codes(out) == []


def test_smoothstep_with_equal_edges_has_no_fix() -> None:
    f = only(shader("float s = smoothstep(0.5, 0.5, sin(iTime));"), "N009")
    # a step on every GPU but at x == edge (some authors use it as one): not an error
    assert f.fix is None and "equal" in f.message and f.severity == "warning"


def test_smoothstep_with_a_positive_width_against_zero_is_reversed_not_equal() -> None:
    # 2/iResolution.y and fwidth(d) touch 0 only as bounds: a reversed anti-aliasing ramp
    for edge in ("2.0 / iResolution.y", "fwidth(sin(iTime))"):
        f = only(shader(f"float s = smoothstep({edge}, 0.0, sin(iTime));"), "N009")
        assert "reversed" in f.message and "equal" not in f.message
        assert f.severity == "warning"


def test_smoothstep_message_shows_the_value_of_a_macro_edge() -> None:
    src = shader("float s = smoothstep(CUE - 1.0, CUE - 3.0, sin(iTime));")
    f = only("#define CUE (14.0 + 10.0 + 5.0 + 19.0)\n" + src, "N009")
    assert "= 47" in f.message and "= 45" in f.message


def test_smoothstep_in_order_is_clean() -> None:
    assert codes(shader("float s = smoothstep(0.0, 0.01, abs(sin(iTime)));")) == []


# --- the valid corpus and the catalog ----------------------------------------------------------

# Correct shaders are clean (16_pbr's h = normalize(v + l) is safe because the one call passes
# v = +z and an l whose y is at least 0.34; sdSegment's dot(ba, ba) is non-zero for every
# segment the file draws), but for one true hazard: 06_macros divides by the distance to a ring,
# abs(length(p) - r), which is 0 on the ring itself (+inf there, which the clamp then hides).
EXPECTED_CORPUS: dict[str, list[str]] = {"06_macros.glsl": ["N005"]}


@pytest.mark.parametrize(
    "path", sorted((ROOT / "tests/corpus/valid").glob("*.glsl")), ids=lambda p: p.name
)
def test_valid_corpus(path: Path) -> None:
    found = codes(path.read_text(encoding="utf-8"))
    assert found == EXPECTED_CORPUS.get(path.name, [])


# The catalog: clean too. (The two cameras' cross(ww, world up) is degenerate only for a view
# straight up or down, a fixed-axis cross product N006 deliberately leaves alone.)
EXPECTED_SNIPPETS: dict[str, list[str]] = {}


@pytest.mark.parametrize(
    "path", sorted((ROOT / "snippets").rglob("*.glsl")), ids=lambda p: str(p.relative_to(ROOT))
)
def test_catalog_snippets(path: Path) -> None:
    found = codes(path.read_text(encoding="utf-8"))
    assert found == EXPECTED_SNIPPETS.get(path.name, [])


# --- precision: what the analysis proves safe -------------------------------------------------


def test_a_guard_on_one_component_protects_the_division() -> None:
    body = "vec3 rd = normalize(vec3(fragCoord, -1.5));\nfloat t = 1.0;\n" \
        "if (rd.y < -1e-4) { t = (-0.8 - 2.0) / rd.y; }"  # fmt: skip
    # (N013 rightly says the guard is never true here: fragCoord.y >= 0, so rd.y >= 0.)
    assert codes(shader(body), "N005") == []


def test_rounding_of_range_bounds_is_not_a_negative_value() -> None:
    body = "vec3 c = max(vec3(fragCoord, 1.0), vec3(0.0));\nc = 1.0 - exp(-2.0 * c);\n" \
        "fragColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);"  # fmt: skip
    assert codes(shader(body)) == []


def test_polar_angle_of_unknown_coordinates_is_not_reported() -> None:
    helper = "float angle(vec2 p) { return atan(p.y, p.x); }\n"
    body = "float a = angle(fragCoord / iResolution.y - vec2(0.5));"
    assert codes(shader(body, helper)) == []


def test_one_finding_per_divisor_on_a_line_with_a_fix_for_every_occurrence() -> None:
    src = shader(
        "float d = distance(fragCoord, vec2(400.0)) * 0.02;\n"
        "fragColor = vec4(0.1 / d, 0.1 / d, 0.2 / d, 0.0);\n"
        "fragColor += vec4(1.0 / d);\n",
        header=False,
    )
    found = [f for f in lint(src) if f.code == "N005"]
    assert len(found) == 2  # one per line, not one per division
    assert found[0].fix is not None and len(found[0].fix.edits) == 3
    options = Options(select=["N005"], glslang=False)
    fixed = lint_text(src, "x.glsl", options, fix=True, unsafe_fixes=True)
    assert fixed.text.count("max(d, 1e-4)") == 4 and "/ d," not in fixed.text


@pytest.mark.parametrize(
    ("base", "plain"),
    [
        ("max(d, 0.0)", True),
        ("max(0.0, d)", True),
        ("clamp(d, 0.0, 1.0)", True),
        ("abs(d)", True),
        ("length(p)", True),
        ("texture(iChannel0, p.xy).x", False),  # a field of the fetch, not the fetch itself
        ("texture(iChannel0, p.xy)", True),
        ("2.0", True),
        ("max(d, -1.0)", False),
        ("clamp(d, -1.0, 1.0)", False),
        ("d", False),
        ("-abs(d)", False),
    ],
)
def test_n001_skips_bases_plainly_never_negative(base: str, plain: bool) -> None:
    """N001 builds the semantic model only for a pow whose base is not plainly never negative
    (the model is most of a default lint run); the skip is sound: such a base has no evidence
    of a negative value to report."""
    from glint.compiler.glsl.parser import parse
    from glint.lint.analysis.syntax import call_args, call_name
    from glint.lint.context import walk_kind
    from glint.lint.rules.numerical._pow import never_negative

    tree = parse(f"float f(float d, vec3 p) {{ return pow({base}, 2.0); }}")
    (call,) = [c for c in walk_kind(tree, "call") if call_name(c) == "pow"]
    assert never_negative(call_args(call)[0]) is plain
    if plain:  # and the rule agrees: nothing to report where the base cannot be negative
        src = shader(f"float d = sin(iTime); vec3 p = vec3(d); float v = pow({base}, 2.0);")
        assert codes(src, "N001") == []
