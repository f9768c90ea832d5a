"""The evaluator against numpy float64 on small handwritten GLSL functions."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.evaluator import EvaluationError, UnsupportedError, evaluate

X = np.linspace(-3.0, 3.0, 61)


def ev(source: str, fn: str, *args: object, dtype: object = np.float64) -> object:
    return evaluate(source, fn, list(args), dtype=dtype)


def test_swizzles_and_write_swizzles() -> None:
    src = """
    vec3 f(vec3 v, float x) {
        vec3 a = v.zyx + vec3(x);
        a.xy = a.yx * 2.0;
        a.z += v.r;
        vec2 b = a.st;
        return vec3(b, a[2]);
    }"""
    v = np.stack([X, 2 * X, 3 * X], -1)
    out = ev(src, "f", v, X)
    a = v[:, ::-1] + X[:, None]
    a[:, :2] = a[:, [1, 0]] * 2
    a[:, 2] += v[:, 0]
    np.testing.assert_allclose(out, a, rtol=0, atol=0)


def test_structs_out_and_inout_params() -> None:
    src = """
    struct P { vec3 pos; float w; };
    P make(float x) { return P(vec3(x, 0.0, 1.0), x * x); }
    void split(P p, out float w, inout vec3 acc) { w = p.w; acc += p.pos; }
    float f(float x) {
        P p = make(x);
        p.pos.y = 2.0;
        float w; vec3 acc = vec3(1.0);
        split(p, w, acc);
        return w + acc.x + acc.y + acc.z;
    }"""
    np.testing.assert_allclose(ev(src, "f", X), X * X + (1 + X) + 3 + 2)
    out = evaluate(src, "split", [{"pos": np.zeros(3), "w": X}, 0.0, np.ones(3)], np.float64)
    np.testing.assert_allclose(out["w"], X)
    np.testing.assert_allclose(out["acc"], np.ones((len(X), 3)))


def test_loop_with_break_and_continue_per_lane() -> None:
    src = """
    float f(float x) {
        float acc = 0.0;
        for (int i = 0; i < 10; i++) {
            if (float(i) > x) break;
            if (i == 2) continue;
            acc += float(i);
        }
        return acc;
    }"""
    expected = [sum(i for i in range(10) if i <= x and i != 2) for x in X]
    np.testing.assert_allclose(ev(src, "f", X), expected)


def test_early_return_under_a_lane_condition() -> None:
    src = """
    float f(float x) {
        if (x < 0.0) return -1.0;
        float y = x * 2.0;
        if (y > 3.0) { return y; } else { y = -y; }
        return y + 0.5;
    }"""
    expected = np.where(X < 0, -1.0, np.where(2 * X > 3, 2 * X, -2 * X + 0.5))
    np.testing.assert_allclose(ev(src, "f", X), expected)


def test_while_until_all_lanes_done() -> None:
    src = "int f(float x) { int n = 0; while (x > 1.0) { x *= 0.5; n++; } return n; }"
    x = np.array([0.5, 2.0, 100.0])
    np.testing.assert_array_equal(ev(src, "f", x), [0, 1, 7])


def test_runaway_loop_is_an_error() -> None:
    src = "float f(float x) { while (x > 0.0) { x += 1.0; } return x; }"
    with pytest.raises(EvaluationError, match="iterations"):
        ev(src, "f", np.array([1.0]))


def test_builtins_match_numpy() -> None:
    src = """
    float m(float x, float y) { return mod(x, y); }
    float s(float x) { return smoothstep(-1.0, 2.0, x); }
    vec3 c(vec3 v) { return clamp(v, -1.0, vec3(0.5, 1.0, 2.0)); }
    vec3 n(vec3 v) { return normalize(v); }
    vec3 r(vec3 i, vec3 nn) { return reflect(i, nn); }
    float t(float y, float x) { return atan(y, x) + step(0.0, x) + fract(x) + sign(y); }
    vec3 mx(vec3 a, vec3 b, float k) { return mix(a, b, k) + cross(a, b); }
    """
    y = np.where(np.arange(len(X)) % 2 == 0, 1.5, -1.5)
    np.testing.assert_allclose(ev(src, "m", X, y), X - y * np.floor(X / y))
    assert ev(src, "m", np.array([-1.0]), 3.0)[0] == 2.0  # GLSL mod follows the divisor's sign
    t = np.clip((X + 1) / 3, 0, 1)
    np.testing.assert_allclose(ev(src, "s", X), t * t * (3 - 2 * t))
    v = np.stack([X, X + 1, -X], -1)
    np.testing.assert_allclose(ev(src, "c", v), np.clip(v, -1, [0.5, 1.0, 2.0]))
    v = v + [0.0, 0.0, 0.1]
    np.testing.assert_allclose(ev(src, "n", v), v / np.linalg.norm(v, axis=-1, keepdims=True))
    nn = np.array([0.0, 1.0, 0.0])
    np.testing.assert_allclose(ev(src, "r", v, nn), v - 2 * (v @ nn)[:, None] * nn)
    expected = np.arctan2(y, X) + (X >= 0) + (X - np.floor(X)) + np.sign(y)
    np.testing.assert_allclose(ev(src, "t", y, X), expected)
    b = v[::-1]
    np.testing.assert_allclose(
        ev(src, "mx", v, b, 0.25), v * 0.75 + b * 0.25 + np.cross(v, b), rtol=1e-12
    )


def test_ternary_logic_and_globals() -> None:
    src = """
    const float K = 2.0;
    #define OFFSET 1.0
    float f(float x) {
        bool big = x > K || x < -K;
        return big && !(x > 0.0) ? OFFSET : (x == 0.0 ? K : -x);
    }"""
    expected = np.where((np.abs(X) > 2) & (X <= 0), 1.0, np.where(X == 0, 2.0, -X))
    np.testing.assert_allclose(ev(src, "f", X), expected)


def test_matrices() -> None:
    src = """
    vec2 f(float a, vec2 v) {
        mat2 r = mat2(cos(a), sin(a), -sin(a), cos(a));
        return r * v + (mat2(2.0) * v) * 0.5 + (v * r) * 0.0;
    }"""
    v = np.array([1.0, 0.0])
    out = ev(src, "f", X, v)
    np.testing.assert_allclose(out, np.stack([np.cos(X) + 1, np.sin(X)], -1), atol=1e-12)


def test_unsupported_and_unknown_names_are_reported_with_their_line() -> None:
    src = "uniform sampler2D tex;\nvec4 f(vec2 uv) {\n  return texture(tex, uv);\n}"
    with pytest.raises(UnsupportedError, match=r"<input>:\d+: type 'sampler2D'|texture"):
        ev(src, "f", np.zeros(2))
    src = "float f(float x) {\n  return dFdx(x);\n}"
    with pytest.raises(UnsupportedError, match=r"<input>:2: 'dFdx'"):
        ev(src, "f", X)
    with pytest.raises(EvaluationError, match=r"<input>:1: unknown function 'map'"):
        ev("float f(vec3 p) { return map(p); }", "f", np.zeros(3))


def test_externals_are_called_with_lanes() -> None:
    src = "float f(vec3 p) { return map(p) * 2.0; }"
    p = np.stack([X, X, X], -1)
    out = evaluate(src, "f", [p], np.float64, externals={"map": lambda q: q[..., 0] + q[..., 1]})
    np.testing.assert_allclose(out, 4 * X)


def test_float16_rounds_and_overflows() -> None:
    src = "float f(float x) { return x * x * x * x; }"
    out = ev(src, "f", np.array([2.0, 20.0]), dtype=np.float16)
    assert out.dtype == np.float16
    assert out[0] == 16.0 and np.isinf(out[1])  # 160000 > 65504, the float16 maximum


def test_do_while_and_return_inside_a_loop() -> None:
    src = """
    float march(float start) {
        float t = start;
        for (int i = 0; i < 100; i++) {
            float d = 5.0 - t;
            if (d < 0.5) return t;
            t += d * 0.5;
            if (t > 4.0) break;
        }
        return -1.0;
    }
    int count(int n) { int k = 0; do { k++; n -= 2; } while (n > 0); return k; }
    """
    out = ev(src, "march", np.array([0.0, 4.6, 4.9]))
    assert out[1] == 4.6 and out[2] == 4.9  # returned on the first iteration
    assert out[0] == -1.0  # t passes 4 and the loop breaks before d < 0.5
    np.testing.assert_array_equal(ev(src, "count", np.array([0, 1, 5], np.int32)), [1, 1, 3])
