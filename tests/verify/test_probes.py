"""GPU probes run a snippet's own GLSL over many inputs; checked here against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.errors import InputError
from glint.compiler.verify.probes import entry_function, probe_inputs, probe_shader, run_probe

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
    assert call.startswith("specular(Surface(") and "in0.x * in0.x, in0.y, in0.x)" in call


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
    gpu = run_probe(
        "F.schlick", {"f00": f0[:, 0], "f01": f0[:, 1], "f02": f0[:, 2], "cosTheta": cos}
    )
    exact = f0 + (1.0 - f0) * (1.0 - cos[:, None]) ** 5
    assert gpu.shape == (600, 3)
    np.testing.assert_allclose(gpu, exact, atol=2e-6)


def test_visibility_probe_passes_the_dots_struct() -> None:
    nol, nov = (g.ravel() for g in np.meshgrid(np.linspace(0.05, 1, 20), np.linspace(0.05, 1, 20)))
    a = np.full_like(nol, 0.4)
    zeros = np.zeros_like(nol)
    inputs = {
        "d.NoL": nol,
        "d.NoV": nov,
        "d.NoH": zeros,
        "d.VoH": zeros,
        "d.LoV": zeros,
        "d.NoLsigned": nol,
        "a": a,
    }
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


def test_probe_of_a_named_helper_returns_two_channels() -> None:
    # ibl's entry is environmentLight; function= probes the vec2 helper it calls instead.
    catalog = load_catalog()
    snippet = catalog.get("ibl.env_brdf_approx")
    _, names, width = probe_shader(snippet, catalog, function="envBRDFApprox")
    assert names == ["NoV", "roughness"] and width == 2
    nov, rough = (g.ravel() for g in np.meshgrid(np.linspace(0, 1, 30), np.linspace(0, 1, 20)))
    gpu = run_probe(
        "ibl.env_brdf_approx", {"NoV": nov, "roughness": rough}, function="envBRDFApprox"
    )
    # Karis's fit, written out in numpy.
    r = rough[:, None] * [-1.0, -0.0275, -0.572, 0.022] + [1.0, 0.0425, 1.04, -0.04]
    grazing = np.minimum(r[:, 0] ** 2, np.exp2(-9.28 * nov)) * r[:, 0] + r[:, 1]
    exact = np.stack([-1.04 * grazing + r[:, 2], 1.04 * grazing + r[:, 3]], axis=1)
    assert gpu.shape == (nov.size, 2)
    np.testing.assert_allclose(gpu, exact, atol=1e-6)


def test_probe_of_an_unknown_function_is_refused() -> None:
    inputs = {"NoV": np.zeros(4), "roughness": np.zeros(4)}
    with pytest.raises(InputError, match="no function envBRDF defined in the snippet"):
        run_probe("ibl.env_brdf_approx", inputs, function="envBRDF")
    # A function the snippet only requires is probed in the snippet that defines it.
    with pytest.raises(InputError, match="it defines: envBRDFApprox, environmentLight"):
        run_probe("ibl.env_brdf_approx", inputs, function="specularOcclusion")
