"""The semantic model: interval arithmetic (with property tests of its soundness), types of
expressions, value ranges through variables and control flow, unit vectors."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from glint.lint.analysis import Interval, Model, semantic_model
from glint.lint.analysis import ranges as R
from glint.lint.context import LintContext, walk
from glint.lint.options import Options
from glint.lint.runner import build_context

# --- helpers --------------------------------------------------------------------------------


def model_of(body: str, helpers: str = "") -> tuple[LintContext, Model]:
    """The model of a ShaderToy shader with `body` inside mainImage."""
    src = helpers + "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n" + body + "\n}\n"
    ctx = build_context(src, "t.glsl", Options(glslang=False))
    assert ctx.tree is not None, ctx.front_end_error
    return ctx, semantic_model(ctx)


def node(ctx: LintContext, text: str, nth: int = -1):  # type: ignore[no-untyped-def]
    """The expression written as `text` (the last one by default)."""
    found = [n for n in walk(ctx.tree) if ctx.node_text(n) == text]  # type: ignore[arg-type]
    assert found, f"no node {text!r}"
    return found[nth]


def rng(body: str, text: str, helpers: str = "", nth: int = -1) -> Interval:
    ctx, model = model_of(body, helpers)
    return model.range_of(node(ctx, text, nth))


UNIT_VECTORS = """
    vec3 a = normalize(vec3(fragCoord, 1.0) - 0.5);
    vec3 b = normalize(vec3(iTime, -1.0, 2.0) * fragCoord.x - 3.0);
"""


# --- Interval ------------------------------------------------------------------------------


def test_interval_questions_and_description() -> None:
    r = Interval(-1.0, 1.0)
    assert r.may_be_negative and r.may_be_zero and r.within(-1, 1) and not r.is_nonnegative
    assert r.describe() == "[-1, 1]"
    assert Interval(0.0, math.inf).describe() == "[0, inf)"
    assert Interval(-math.inf, 2.5).describe() == "(-inf, 2.5]"
    assert Interval().describe() == "unknown" and Interval().is_unknown
    assert Interval(1e-4, 1.0).is_positive and not Interval(1e-4, 1.0).may_be_zero


def test_division_by_an_interval_with_zero_inside_is_unknown() -> None:
    assert (Interval(1, 2) / Interval(-1, 1)).is_unknown
    assert Interval(1, 2) / Interval(0, 2) == Interval(0.5, math.inf)
    assert Interval(1, 2) / Interval(2, 4) == Interval(0.25, 1.0)


def test_nan_bounds_widen_instead_of_poisoning_comparisons() -> None:
    assert (Interval(0, math.inf) * Interval(-math.inf, 0)).lo == -math.inf
    assert Interval(math.nan, 1.0).lo == -math.inf


def test_sin_and_cos_of_a_narrow_range_are_tight() -> None:
    assert R.sin_range(Interval(0.0, 1.0)) == Interval(0.0, math.sin(1.0))
    assert R.cos_range(Interval(-0.5, 0.5)).lo == pytest.approx(math.cos(0.5))
    assert R.cos_range(Interval(-0.5, 0.5)).hi == 1.0
    assert R.sin_range(Interval(0.0, math.inf)) == R.UNIT


@pytest.mark.parametrize("x", [1e20, -1e20, 2.0**53, 1e300])
def test_sin_and_cos_of_a_huge_value_end(x: float) -> None:
    # Past 2^53, `k * pi` stopped growing with k: the walk over the extrema never ended (a
    # loop's widening grows values that far; lint ran out of memory on 2 KB of code).
    for f in (R.sin_range, R.cos_range):
        assert f(Interval.point(x)) == R.UNIT
        assert f(Interval(x, x + 1.0)) == R.UNIT


def test_tan_poles() -> None:
    assert R.reaches_tan_pole(Interval(1.0, 2.0))
    assert not R.reaches_tan_pole(Interval(-1.0, 1.0))
    assert R.reaches_tan_pole(Interval(0.0, math.inf))
    assert not R.reaches_tan_pole(Interval())  # unknown reports nothing


# --- soundness: sampled points of the operands land inside the result ------------------------

finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


@st.composite
def intervals(draw: st.DrawFn, lo: float = -1e6, hi: float = 1e6) -> tuple[Interval, float]:
    """An interval and a point inside it."""
    values = st.floats(min_value=lo, max_value=hi, allow_nan=False)
    a, b = sorted((draw(values), draw(values)))
    t = draw(st.floats(min_value=0.0, max_value=1.0))
    x = min(max(a + (b - a) * t, a), b)
    return Interval(a, b), x


BINARY = {
    "add": (lambda p, q: p + q, lambda x, y: x + y),
    "sub": (lambda p, q: p - q, lambda x, y: x - y),
    "mul": (lambda p, q: p * q, lambda x, y: x * y),
    "min": (Interval.min, min),
    "max": (Interval.max, max),
}


@pytest.mark.parametrize("op", sorted(BINARY))
@settings(max_examples=200, deadline=None)
@given(a=intervals(), b=intervals())
def test_binary_operations_are_sound(op: str, a: tuple, b: tuple) -> None:
    (p, x), (q, y) = a, b
    interval_op, float_op = BINARY[op]
    assert interval_op(p, q).contains(float_op(x, y))


@settings(max_examples=300, deadline=None)
@given(a=intervals(), b=intervals())
def test_division_is_sound(a: tuple, b: tuple) -> None:
    (p, x), (q, y) = a, b
    if y != 0:
        assert (p / q).contains(x / y)


@settings(max_examples=200, deadline=None)
@given(a=intervals(), b=intervals(-1e3, 1e3), c=intervals(-1e3, 1e3))
def test_clamp_and_mix_are_sound(a: tuple, b: tuple, c: tuple) -> None:
    (p, x), (q, y), (r, z) = a, b, c
    if q.hi <= r.lo:
        assert p.clamp(q, r).contains(min(max(x, y), z))
    t = (z + 1e3) / 2e3  # a mix weight in [0, 1]
    weight = Interval((r.lo + 1e3) / 2e3, (r.hi + 1e3) / 2e3)
    out, value = R.mix_range(p, q, weight), x * (1 - t) + y * t
    tolerance = 1e-9 * (abs(x) + abs(y)) + 1e-300  # x(1 - t) + yt rounds; ranges are real
    assert out.lo - tolerance <= value <= out.hi + tolerance


UNARY = {
    "neg": (lambda p: -p, lambda x: -x),
    "square": (Interval.square, lambda x: x * x),
    "abs": (Interval.abs, abs),
    "sin": (R.sin_range, math.sin),
    "cos": (R.cos_range, math.cos),
    "floor": (R.floor_like(math.floor), math.floor),
    "fract": (R.fract_range, lambda x: x - math.floor(x)),
    "sign": (R.sign_range, lambda x: (x > 0) - (x < 0)),
    "atan": (lambda p: R.atan_range(p, None), math.atan),
}


@pytest.mark.parametrize("op", sorted(UNARY))
@settings(max_examples=200, deadline=None)
@given(a=intervals())
def test_unary_functions_are_sound(op: str, a: tuple) -> None:
    p, x = a
    interval_op, float_op = UNARY[op]
    assert interval_op(p).contains(float_op(x))


@settings(max_examples=200, deadline=None)
@given(a=intervals(-700, 700), b=intervals(1e-9, 1e6), e=st.floats(-8, 8))
def test_exp_log_sqrt_pow_are_sound(a: tuple, b: tuple, e: float) -> None:
    (p, x), (q, y) = a, b
    assert R.exp_range(p).contains(math.exp(x))
    assert R.sqrt_range(q).contains(math.sqrt(y))
    assert R.log_range(q).contains(math.log(y))
    assert R.inversesqrt_range(q).contains(1 / math.sqrt(y))
    try:
        value = y**e
    except OverflowError:
        return
    assert R.pow_range(q, Interval.point(e)).contains(value)


@settings(max_examples=200, deadline=None)
@given(a=intervals(), b=intervals(1e-3, 1e3))
def test_mod_is_sound(a: tuple, b: tuple) -> None:
    (p, x), (q, y) = a, b
    # the real-number mod (Python's float % rounds it correctly); the textbook float formula
    # x - y * floor(x / y) can dip a hair below 0, which no rule should report
    assert R.mod_range(p, q).contains(x % y)


# --- types ---------------------------------------------------------------------------------


def test_types_of_swizzles_constructors_and_builtins() -> None:
    ctx, model = model_of(
        """
        vec4 c = vec4(1.0);
        vec3 n = normalize(c.xyz);
        float d = dot(n, n);
        mat3 m = mat3(1.0);
        ivec2 i = ivec2(2, 3);
        vec4 t = texture(iChannel0, fragCoord / iResolution.xy);
        fragColor = vec4(m * n, d) + t + vec4(cross(n, n).zy, i.x, length(c));
        """
    )
    expect = {
        "c.xyz": "vec3",
        "normalize(c.xyz)": "vec3",
        "dot(n, n)": "float",
        "m * n": "vec3",
        "cross(n, n).zy": "vec2",
        "i.x": "int",
        "iResolution.xy": "vec2",
        "texture(iChannel0, fragCoord / iResolution.xy)": "vec4",
        "length(c)": "float",
        "vec4(1.0)": "vec4",
        "fragCoord": "vec2",
        "iTime": None,  # not used: the lookup is by text
    }
    for text, ty in expect.items():
        if ty is not None:
            assert model.type_of(node(ctx, text)) == ty, text


def test_types_of_struct_fields_arrays_and_user_functions() -> None:
    helpers = """
    struct Light { vec3 dir; float power[2]; };
    Light sun() { return Light(vec3(0.0, 1.0, 0.0), float[2](1.0, 2.0)); }
    """
    ctx, model = model_of(
        "Light l = sun();\nfloat p = l.power[1];\nvec2 d = l.dir.xz;\nbool k = p > 1.0;",
        helpers,
    )
    assert model.type_of(node(ctx, "sun()")) == "Light"
    assert model.type_of(node(ctx, "l.power")) == "float[2]"
    assert model.type_of(node(ctx, "l.power[1]")) == "float"
    assert model.type_of(node(ctx, "l.dir.xz")) == "vec2"
    assert model.type_of(node(ctx, "p > 1.0")) == "bool"


def test_types_follow_scopes() -> None:
    ctx, model = model_of("float x = 1.0;\n{ vec3 x = vec3(2.0); fragColor.rgb = x; }\nx += 1.0;")
    xs = [n for n in walk(ctx.tree) if n.data == "variable" and ctx.node_text(n) == "x"]
    assert [model.type_of(x) for x in xs] == ["vec3", "float"]


def test_shadertoy_uniforms() -> None:
    ctx, model = model_of("fragColor = vec4(iTime, iMouse.x, float(iFrame), iDate.w);")
    assert model.type_of(node(ctx, "iTime")) == "float"
    assert model.type_of(node(ctx, "iMouse")) == "vec4"
    assert model.type_of(node(ctx, "iFrame")) == "int"
    assert model.range_of(node(ctx, "iTime")).is_nonnegative


# --- ranges ------------------------------------------------------------------------------


def test_clamped_dot_of_unit_vectors_is_zero_to_one() -> None:
    body = UNIT_VECTORS + "float d = max(dot(a, b), 0.0);"
    assert rng(body, "max(dot(a, b), 0.0)") == Interval(0.0, 1.0)
    assert rng(body, "dot(a, b)") == Interval(-1.0, 1.0)


def test_dot_of_a_vector_with_itself_and_squares_are_not_negative() -> None:
    body = "vec2 p = fragCoord - 100.0; float x = p.x - 3.0;\nfloat s = dot(p, p) + x * x;"
    assert rng(body, "dot(p, p)").is_nonnegative
    assert rng(body, "x * x").is_nonnegative
    assert rng(body, "p.x - 3.0").may_be_negative


def test_builtin_ranges() -> None:
    body = """
    float t = iTime;
    float a = sin(t) + cos(t);
    float b = fract(t);
    float c = smoothstep(0.0, 1.0, t) + step(0.5, t);
    float d = exp(-t);
    float e = sqrt(t) + length(fragCoord);
    float f = clamp(t, -2.0, 3.0);
    float g = mix(-1.0, 4.0, b);
    float h = abs(sin(t) - 2.0);
    float k = pow(t, 2.0);
    vec2 uv = fragCoord / iResolution.xy;
    """
    ctx, model = model_of(body)

    def r(text: str) -> Interval:
        return model.range_of(node(ctx, text))

    assert r("sin(t) + cos(t)") == Interval(-2.0, 2.0)
    assert r("fract(t)") == Interval(0.0, 1.0)
    assert r("smoothstep(0.0, 1.0, t)").within(0, 1) and r("step(0.5, t)").within(0, 1)
    assert r("exp(-t)").is_positive and r("exp(-t)").hi == pytest.approx(1.0)
    assert r("sqrt(t) + length(fragCoord)").is_nonnegative
    assert r("clamp(t, -2.0, 3.0)") == Interval(0.0, 3.0)  # iTime >= 0
    assert r("mix(-1.0, 4.0, b)") == Interval(-1.0, 4.0)
    assert r("abs(sin(t) - 2.0)") == Interval(1.0, 3.0)
    assert r("pow(t, 2.0)").is_nonnegative
    assert r("iResolution.xy").is_positive and r("fragCoord / iResolution.xy").is_nonnegative


def test_macros_are_literals_after_preprocessing() -> None:
    helpers = "#define SHININESS 32.0\n#define EPS 1e-3\n"
    ctx, model = model_of("float e = max(SHININESS, EPS);", helpers)
    call = next(n for n in walk(ctx.tree) if n.data == "call")  # type: ignore[arg-type]
    assert model.range_of(call) == Interval(32.0, 32.0)


def test_if_else_joins_by_the_hull() -> None:
    body = "float x = 1.0;\nif (iTime > 3.0) { x = -2.0; } else { x = 5.0; }\nfloat y = x;"
    assert rng(body, "x") == Interval(-2.0, 5.0)


def test_an_if_without_else_keeps_the_old_value_in_the_hull() -> None:
    body = "float x = 1.0;\nif (iTime > 3.0) x = 7.0;\nfloat y = x;"
    assert rng(body, "x") == Interval(1.0, 7.0)


def test_conditions_narrow_the_compared_variable() -> None:
    body = "float x = sin(iTime);\nif (x > 0.0) { fragColor = vec4(sqrt(x)); }"
    assert rng(body, "x", nth=-1) == Interval(5e-324, 1.0)  # strict: 0 itself is excluded
    body = "float x = sin(iTime);\nif (x < 0.25) return;\nfloat y = x;"
    assert rng(body, "x") == Interval(0.25, 1.0)
    body = "float x = sin(iTime);\nfloat y = x > 0.5 ? x : 0.5;"
    assert rng(body, "x > 0.5 ? x : 0.5") == Interval(0.5, 1.0)


def test_loops_widen_what_they_assign() -> None:
    body = "float t = 0.0;\nfor (int i = 0; i < 8; i++) { t += 0.5; }\nfloat u = t;"
    assert rng(body, "t").is_unknown
    body = "float k = 2.0;\nfor (int i = 0; i < 8; i++) { fragColor += 1.0; }\nfloat u = k;"
    assert rng(body, "k").is_point


def test_loop_exit_through_break_is_joined() -> None:
    body = """
    float d = 1.0;
    for (int i = 0; i < 4; i++) { if (iTime > 1.0) { d = -1.0; break; } }
    float e = d;
    """
    assert rng(body, "d").is_unknown or rng(body, "d").contains(-1.0)


def test_reassignment_in_source_order() -> None:
    body = "float x = -1.0;\nx = abs(x) + 1.0;\nx *= 2.0;\nfloat y = x;"
    assert rng(body, "x") == Interval(4.0, 4.0)


def test_chained_assignments_take_the_value_assigned() -> None:
    # `x = (y = y + 1.0)`: x takes y's new value, evaluated once (the right side was evaluated
    # again after y had changed, and once per `=` of a chain: quadratic in its length).
    body = "float y = 1.0;\nfloat x = 0.0;\nx = (y = y + 1.0);\nfloat a = x;\nfloat b = y;"
    assert rng(body, "x") == Interval(2.0, 2.0)
    assert rng(body, "y") == Interval(2.0, 2.0)
    body = "float y = 1.0;\nfloat x = 0.0;\nx += y *= 3.0;\nfloat a = x;\nfloat b = y;"
    assert rng(body, "x") == Interval(3.0, 3.0)
    assert rng(body, "y") == Interval(3.0, 3.0)


def test_globals_and_consts() -> None:
    helpers = "const float K = 2.0;\nfloat g = 1.0;\nvoid bump() { g = -5.0; }\n"
    ctx, model = model_of("float a = K;\nfloat b = g;", helpers)
    assert model.range_of(node(ctx, "K")).is_point
    assert model.range_of(node(ctx, "g", nth=-1)).is_unknown  # assigned in a function


def test_user_function_results_and_call_site_parameters() -> None:
    helpers = """
    float sat(float x) { return clamp(x, 0.0, 1.0); }
    float half_(float v) { return v * 0.5; }
    """
    ctx, model = model_of("float a = sat(iTime * 3.0);\nfloat b = half_(4.0);", helpers)
    assert model.range_of(node(ctx, "sat(iTime * 3.0)")) == Interval(0.0, 1.0)
    assert model.range_of(node(ctx, "v * 0.5")) == Interval(2.0, 2.0)  # the only call passes 4


def test_uncalled_helpers_know_nothing_of_their_parameters() -> None:
    ctx, model = model_of("", "float f(float x) { return x * 2.0; }")
    assert model.range_of(node(ctx, "x * 2.0")).is_unknown


def test_out_arguments_forget_the_variable() -> None:
    helpers = "void set(out float v) { v = -3.0; }\n"
    assert rng("float x = 1.0;\nset(x);\nfloat y = x;", "x", helpers).is_unknown


# --- unit vectors -------------------------------------------------------------------------


def test_unit_vectors() -> None:
    helpers = "vec3 calcNormal(vec3 p) { return normalize(p); }\n"
    body = (
        UNIT_VECTORS
        + """
    vec3 n = calcNormal(a);
    vec3 r = reflect(-a, n);
    vec3 up = vec3(0.0, 1.0, 0.0);
    vec3 s = a + b;
    vec3 w = a;
    w = w * 2.0;
    fragColor = vec4(r + n + up + s + w, 1.0);
    """
    )
    ctx, model = model_of(body, helpers)
    assert model.is_unit(node(ctx, "calcNormal(a)"))
    assert model.is_unit(node(ctx, "reflect(-a, n)"))
    assert model.is_unit(node(ctx, "vec3(0.0, 1.0, 0.0)"))
    assert model.is_unit(node(ctx, "n", nth=-1))
    assert not model.is_unit(node(ctx, "a + b"))
    assert not model.is_unit(node(ctx, "w", nth=-1))  # scaled after it was assigned a unit
    assert model.origin_of(node(ctx, "a + b")) == "sum"


def test_dot_with_a_unit_vector_is_bounded_by_the_other_length() -> None:
    body = UNIT_VECTORS + "float k = dot(a, vec3(0.0, 2.0, 0.0));"
    assert rng(body, "dot(a, vec3(0.0, 2.0, 0.0))").within(-2.0, 2.0)


def test_deep_nesting_raises_recursion_error_the_runner_reports() -> None:
    from glint.lint.runner import lint_source

    deep = "(" * 3000 + "1.0" + ")" * 3000
    src = f"void mainImage(out vec4 c, in vec2 p) {{ float x = {deep}; c = vec4(x); }}"
    findings = lint_source(src, "deep.glsl", Options(select=["N", "C006"], glslang=False))
    assert all(f.code == "C006" for f in findings)


def test_switch_joins_the_cases_and_the_fall_through() -> None:
    body = """
    float x = 0.0;
    switch (iFrame) {
        case 0: x = 1.0; break;
        case 1: x = 2.0;
        default: x += 5.0;
    }
    float y = x;
    """
    assert rng(body, "x") == Interval(1.0, 7.0)


def test_while_and_do_loops_narrow_on_exit() -> None:
    body = "float x = iTime;\nwhile (x > 1.0) { x -= 1.0; }\nfloat y = x;"
    assert rng(body, "x").hi == 1.0
    body = "float x = 4.0;\ndo { x *= 0.5; } while (x > 2.0);\nfloat y = x;"
    assert rng(body, "x").hi == 2.0


def test_deeply_nested_loops_stay_fast() -> None:
    import time

    body = "float t = 0.0;\nvec3 n = normalize(vec3(1.0));\n"
    for i in range(12):
        body += f"for (int i{i} = 0; i{i} < 4; i{i}++) {{ t += 1.0; n = normalize(n + t); "
    body += "}" * 12
    start = time.perf_counter()
    ctx, model = model_of(body)
    assert model.range_of(node(ctx, "t", nth=-1)).is_unknown
    assert time.perf_counter() - start < 5.0


def test_invalid_code_gives_unknowns_not_crashes() -> None:
    ctx, model = model_of("vec2 v = vec2(1.0);\nfloat z = v.z + undefinedThing.x * foo(3.0);")
    assert model.range_of(node(ctx, "v.z")).is_unknown
    assert model.type_of(node(ctx, "foo(3.0)")) is None


# --- knowledge beyond interval arithmetic ----------------------------------------------------


def test_the_smoothstep_polynomial_stays_in_zero_one() -> None:
    # value noise's Hermite weight: t*t*(3 - 2t) maps [0, 1] onto [0, 1], not [0, 3]
    body = "float f = fract(iTime);\nfloat w = f*f*(3.0-2.0*f);"
    assert rng(body, "f*f*(3.0-2.0*f)") == Interval(0.0, 1.0)
    body = "vec2 f = fract(fragCoord);\nf = f*f*(3.-2.*f);\nvec2 g = f;"
    assert rng(body, "f") == Interval(0.0, 1.0)
    body = "float t = fract(iTime);\nfloat q = t*t*t*(t*(t*6.0-15.0)+10.0);"
    assert rng(body, "t*t*t*(t*(t*6.0-15.0)+10.0)") == Interval(0.0, 1.0)
    # a contrast curve: 0.7c + 0.3c^2(3 - 2c) of c in [0, 1]
    body = "float c = clamp(sin(iTime), 0.0, 1.0);\nfloat k = c*0.7 + 0.3*c*c*(3.0-2.0*c);"
    r = rng(body, "c*0.7 + 0.3*c*c*(3.0-2.0*c)")  # 0.3 * 3.0 rounds: within an ulp of [0, 1]
    assert r.lo == 0.0 and abs(r.hi - 1.0) < 1e-12
    # a polynomial with an extremum inside: (x - 1)^2 on [-1, 3] is [0, 4] up to the root
    r = R.poly_range([1.0, -2.0, 1.0], Interval(-1.0, 3.0))
    assert -1e-9 < r.lo <= 0.0 and r.hi == 4.0


@given(st.floats(-3, 3), st.floats(0, 3), st.lists(st.floats(-5, 5), min_size=1, max_size=6))
@settings(max_examples=200, deadline=None)
def test_poly_range_contains_every_value(lo: float, width: float, coeffs: list[float]) -> None:
    r = R.poly_range(coeffs, Interval(lo, lo + width))
    for k in range(11):
        x = lo + width * k / 10
        v = sum(c * x**i for i, c in enumerate(coeffs))
        assert r.lo - 1e-9 * (1 + abs(v)) <= v <= r.hi + 1e-9 * (1 + abs(v))


def test_a_positive_constant_over_the_resolution_is_positive() -> None:
    # iResolution is finite (no framebuffer is wider than 16384): 2/iResolution.y > 0; and a
    # canvas has at least MIN_CANVAS (16) pixels a side
    r = rng("float px = 2.0 / iResolution.y;", "2.0 / iResolution.y")
    assert r.lo > 0 and r.hi == 2.0 / 16.0


def test_a_strict_comparison_keeps_the_length_away_from_zero() -> None:
    body = "vec2 uv = fragCoord - 0.5;\nfloat a = (uv.x > 0.0) ? uv.y / length(uv) : 0.0;"
    assert rng(body, "length(uv)").lo > 0


def test_guards_relate_two_variables() -> None:
    # inside `if (c < rq)`: rq - c > 0 however both vary
    body = "float rq = sin(iTime);\nfloat c = cos(iTime);\nif (c < rq) { float l = sqrt(rq - c); }"
    assert rng(body, "rq - c").lo > 0
    # after `if (r2 > sr2) return;`: sr2 - r2 >= 0
    body = (
        "float sr2 = sin(iTime);\nfloat r2 = cos(iTime);\n"
        "if (r2 > sr2) return;\nfloat e = sr2 - r2;"
    )
    assert rng(body, "sr2 - r2").lo == 0
    # 0 <= y < s.w: s.w*s.w - y*y >= 0; and y / s.w in [0, 1]
    body = (
        "vec4 s = vec4(sin(iTime));\nfloat y = length(fragCoord);\n"
        "if (y < s.w) { float x = s.w*s.w - y*y; float r = y / s.w; }"
    )
    assert rng(body, "s.w*s.w - y*y").lo == 0
    assert rng(body, "y / s.w") == Interval(0.0, 1.0)
    # a reassignment after the guard ends the relation
    body = (
        "float a = sin(iTime);\nfloat b = cos(iTime);\n"
        "if (b < a) { b = 2.0 * iTime; float d = a - b; }"
    )
    assert rng(body, "a - b").lo < 0
