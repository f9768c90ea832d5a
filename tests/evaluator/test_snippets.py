"""Real catalog snippets evaluated by their own code, against closed forms and numpy."""

from __future__ import annotations

import numpy as np

from glint.compiler.compose.linking.snippet_evaluation import evaluate_snippet, snippet_units


def grid(n: int = 64) -> tuple[np.ndarray, np.ndarray]:
    noh, a = np.meshgrid(np.linspace(0, 1, n), np.linspace(0.05, 1, n), indexing="ij")
    return noh.ravel(), a.ravel()


def test_dependencies_come_first() -> None:
    ids = [s.id for s in snippet_units("specular.cook_torrance")]
    assert ids[-1] == "specular.cook_torrance"
    assert ids.index("core.constants") < ids.index("D.ggx")
    assert {"core.surface", "V.smith_ggx_correlated"} <= set(ids)


def test_ggx_matches_the_closed_form() -> None:
    noh, a = grid()
    out = evaluate_snippet("D.ggx", args={"NoH": noh, "a": a}, dtype=np.float64)
    pi = 3.14159265359  # the catalog's PI, as written
    a2 = a * a
    expected = a2 / (pi * (noh * noh * (a2 - 1) + 1) ** 2)
    np.testing.assert_allclose(out, expected, rtol=1e-12, atol=0)


def test_smith_ggx_correlated_with_a_dots_struct() -> None:
    nov, a = grid(32)
    nol = nov[::-1].copy()
    dots = {"NoL": nol, "NoV": nov, "NoH": nov, "VoH": nov, "LoV": nov, "NoLsigned": nol}
    out = evaluate_snippet("V.smith_ggx_correlated", args=[dots, a], dtype=np.float64)
    a2 = a * a
    gv = nol * np.sqrt(nov * nov * (1 - a2) + a2)
    gl = nov * np.sqrt(nol * nol * (1 - a2) + a2)
    np.testing.assert_allclose(out, 0.5 / np.maximum(gv + gl, 1e-5), rtol=1e-12)


def test_schlick_with_vec3_f0() -> None:
    cos = np.linspace(0, 1, 11)
    f0 = np.array([0.04, 0.5, 0.95])
    out = evaluate_snippet("F.schlick", args=[f0, cos], dtype=np.float64)
    expected = f0 + (1 - f0) * (1 - cos[:, None]) ** 5
    np.testing.assert_allclose(out, expected, rtol=1e-12)


def test_reinhard_and_srgb_on_vec3() -> None:
    c = np.random.default_rng(1).uniform(0, 4, size=(100, 3))
    out = evaluate_snippet("tonemap.reinhard", args=[c], dtype=np.float64)
    np.testing.assert_allclose(out, c / (c + 1), rtol=1e-12)
    c = c / 4 - 0.05
    out = evaluate_snippet("output.srgb", args=[c], dtype=np.float64)
    x = np.maximum(c, 0)
    expected = np.where(x >= 0.0031308, 1.055 * x ** (1 / 2.4) - 0.055, 12.92 * x)
    np.testing.assert_allclose(out, expected, rtol=1e-12)


def sphere(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(p - np.array([0.0, 1.5, 0.0]), axis=-1) - 1.0


def soft_shadow(ro: np.ndarray, rd: np.ndarray, tmin: float, tmax: float) -> np.ndarray:
    """The loop of shadow.soft, one lane at a time (SHADOW_STEPS 24, SHADOW_K 8)."""
    out = []
    for o in ro:
        res, t = 1.0, tmin
        for _ in range(24):
            h = float(sphere(o + rd * t))
            res = min(res, 8.0 * h / t)
            t += min(max(h, 0.02), 0.2)
            if res < 0.001 or t > tmax:
                break
        out.append(min(max(res, 0.0), 1.0))
    return np.array(out)


def test_soft_shadow_with_an_external_map() -> None:
    x = np.linspace(-2.5, 2.5, 41)
    ro = np.stack([x, np.zeros_like(x), np.zeros_like(x)], -1)
    rd = np.array([0.0, 1.0, 0.0])
    out = evaluate_snippet(
        "shadow.soft", args=[ro, rd, 0.02, 10.0], dtype=np.float64, externals={"map": sphere}
    )
    np.testing.assert_allclose(out, soft_shadow(ro, rd, 0.02, 10.0), rtol=1e-12, atol=1e-15)
    assert out.min() == 0.0 and out.max() == 1.0  # both umbra and lit lanes in one call
