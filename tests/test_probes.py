"""GPU probes run a snippet's own GLSL over many inputs; checked here against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog import load_catalog
from glint.compiler.errors import InputError
from glint.compiler.probes import entry_function, probe_inputs, run_probe

pytestmark = pytest.mark.render


def test_probe_inputs_flatten_vectors_and_structs() -> None:
    catalog = load_catalog()
    names, call = probe_inputs(entry_function(catalog.get("F.schlick")))
    assert names == ["f00", "f01", "f02", "cosTheta"]
    assert call == "fresnel(vec3(in0.x, in0.y, in0.z), in0.w)"
    names, call = probe_inputs(entry_function(catalog.get("V.smith_ggx_correlated")))
    assert names == ["d.NoL", "d.NoV", "d.NoH", "d.VoH", "d.LoV", "d.NoLsigned", "a"]
    assert call == "visibility(Dots(in0.x, in0.y, in0.z, in0.w, in1.x, in1.y), in1.z)"
    names, call = probe_inputs(entry_function(catalog.get("specular.cook_torrance")))
    assert names[:2] == ["s.roughness", "s.NoV"] and names[-3:] == ["F0", "F1", "F2"]
    assert call.startswith("specular(Surface(") and "in0.x * in0.x, in0.y)" in call


def test_ggx_probe_matches_its_closed_form() -> None:
    noh, a = np.meshgrid(np.linspace(0.0, 0.999, 40), np.linspace(0.05, 1.0, 30))
    noh, a = noh.ravel(), a.ravel()
    gpu = run_probe("D.ggx", {"NoH": noh, "a": a})
    a2 = a * a
    exact = a2 / (np.pi * (noh * noh * (a2 - 1.0) + 1.0) ** 2)
    assert gpu.shape == (noh.size,)
    np.testing.assert_allclose(gpu, exact, rtol=2e-5)


def test_schlick_probe_returns_three_channels() -> None:
    cos = np.linspace(0.0, 1.0, 600)
    f0 = np.stack([np.full_like(cos, 0.04), np.full_like(cos, 0.5), np.ones_like(cos)], axis=1)
    gpu = run_probe("F.schlick", {"f00": f0[:, 0], "f01": f0[:, 1], "f02": f0[:, 2],
                                  "cosTheta": cos})
    exact = f0 + (1.0 - f0) * (1.0 - cos[:, None]) ** 5
    assert gpu.shape == (600, 3)
    np.testing.assert_allclose(gpu, exact, atol=2e-6)


def test_visibility_probe_passes_the_dots_struct() -> None:
    nol, nov = (g.ravel() for g in np.meshgrid(np.linspace(0.05, 1, 20), np.linspace(0.05, 1, 20)))
    a = np.full_like(nol, 0.4)
    zeros = np.zeros_like(nol)
    inputs = {"d.NoL": nol, "d.NoV": nov, "d.NoH": zeros, "d.VoH": zeros, "d.LoV": zeros,
              "d.NoLsigned": nol, "a": a}
    gpu = run_probe("V.smith_ggx_correlated", inputs)
    a2 = a * a
    lambda_v = nol * np.sqrt(nov * nov * (1 - a2) + a2)
    lambda_l = nov * np.sqrt(nol * nol * (1 - a2) + a2)
    exact = 0.5 / (lambda_v + lambda_l)
    np.testing.assert_allclose(gpu, exact, rtol=1e-5)


def test_missing_input_is_named() -> None:
    with pytest.raises(InputError, match="probe inputs missing: a"):
        run_probe("D.ggx", {"NoH": np.zeros(4)})


def test_entry_with_out_parameters_cannot_be_probed() -> None:
    with pytest.raises(InputError, match="cannot probe an out parameter"):
        probe_inputs(entry_function(load_catalog().get("camera.orbit")))
