"""Half precision (mediump) behaviour of the catalog, measured with the CPU evaluator."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.compose.linking.snippet_evaluation import evaluate_snippet
from glint.compiler.verify.precision import default_grid, precision_report, survey


def ggx(noh: np.ndarray, a: float, dtype: object) -> np.ndarray:
    return evaluate_snippet("D.ggx", args=[noh, a], dtype=dtype)


def test_ggx_overflows_in_float16_at_the_peak_of_smooth_surfaces() -> None:
    noh = np.array([1.0])
    for a in (0.002, 0.01):
        # a² − 1 rounds to −1 in half precision, so d = 0 and D = a²/0
        assert np.isinf(ggx(noh, a, np.float16)).all()
        assert np.isfinite(ggx(noh, a, np.float32)).all()
    np.testing.assert_allclose(ggx(noh, 0.01, np.float64), 1 / (np.pi * 1e-4), rtol=1e-9)


def test_ggx_loses_precision_in_float16_near_the_peak() -> None:
    noh = np.array([0.9999, 0.999])  # 0.9999 is 1.0 in float16
    ref = ggx(noh, 0.05, np.float64)
    half = ggx(noh, 0.05, np.float16).astype(np.float64)
    rel = np.abs(half - ref) / ref
    assert rel[0] > 0.2  # measured: 133.5 against 109.2
    assert rel[1] > 0.04  # measured: 41.2 against 39.4
    single = ggx(noh, 0.05, np.float32).astype(np.float64)
    assert np.max(np.abs(single - ref) / ref) < 1e-4


def test_precision_report_of_ggx() -> None:
    report = precision_report("D.ggx")
    assert set(report) == {"float16", "float32", "float64"}
    assert report["float16"]["finite"] is False
    assert report["float16"]["nonfinite_lanes"] >= 1
    assert report["float32"]["finite"] and report["float64"]["finite"]
    assert report["float64"]["max_rel_err_vs_f64"] == 0.0
    assert report["float32"]["max_rel_err_vs_f64"] < 0.01


def test_report_on_a_given_grid() -> None:
    grid = {"NoH": np.linspace(0, 0.9, 50), "a": np.full(50, 0.5)}
    report = precision_report("D.ggx", grid)
    assert report["float16"]["finite"]
    assert report["float16"]["max_rel_err_vs_f64"] < 5e-3


MEDIUMP = sorted(i for i in load_catalog().snippets if i.endswith("_mediump"))


@pytest.mark.parametrize("snippet_id", MEDIUMP)
def test_mediump_variants_stay_finite_in_float16(snippet_id: str) -> None:
    report = precision_report(snippet_id, default_grid(snippet_id, points=16384))
    assert report["float16"]["finite"], report


def test_survey_covers_the_simple_slots_and_float32_is_finite() -> None:
    results = survey(points=1024)
    assert {"D.ggx", "F.schlick", "V.smith_ggx_correlated", "tonemap.reinhard"} <= set(results)
    assert "camera.orbit" not in results  # vec2 and out parameters: not a simple entry
    for snippet_id, report in results.items():
        assert report["float32"]["finite"], snippet_id
