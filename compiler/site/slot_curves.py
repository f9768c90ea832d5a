"""One chart per surface slot that overlays every variant over the angle that matters, with the
float64 reference of the variant the reference tier takes: what Disney's BRDF Explorer shows as
lobe plots, here with glint's own GPU evaluation of each snippet (compiler/verify/probes.py) and
its own references (compiler/verify/references).

    D:        D(h) over the half-vector angle, at two roughnesses (log scale)
    F:        F over the angle of incidence, at f0 = 0.04 (a dielectric)
    V:        V over the light's angle, view at 45 degrees, roughness 0.5
    diffuse:  the diffuse lobe over the light's angle, view at 45 degrees, roughness 0.5
    specular: the specular lobe over the light's angle, in the mirror plane, roughness 0.5

The curves are data first (`slot_curves`), drawn second, so that a test holds the data to what
the chart claims: the reference tier's variant lies on its reference.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import glint
from glint.compiler.bench.samples import probe_arguments, reference_values
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.errors import InputError
from glint.compiler.files import write_atomic
from glint.compiler.verify.probes import run_probe

from .measured import figure_png, pyplot

CURVES_VERSION = "1"  # bump when the chart's look or its sweeps change
ANGLES = np.linspace(0.0, 89.0, 90)  # degrees: the x axis of every chart
_COS = np.cos(np.radians(ANGLES))
_VIEW = np.cos(np.radians(45.0))


@dataclass(frozen=True)
class Sweep:
    label: str  # the x axis
    ylabel: str
    cases: tuple[tuple[str, dict[str, float]], ...]  # (legend suffix, fixed inputs) per panel
    swept: str  # the base input the angle sets (its cosine)
    log: bool = False


SWEEPS = {
    "D": Sweep(
        "half-vector angle θh (degrees)",
        "D",
        (("roughness 0.3", {"a": 0.09}), ("roughness 0.6", {"a": 0.36})),
        "NoH",
        log=True,
    ),  # fmt: skip
    "F": Sweep("angle of incidence (degrees)", "F", (("f0 = 0.04", {"f0": 0.04}),), "cosTheta"),
    "V": Sweep(
        "light angle θl (degrees)", "V", (("roughness 0.5", {"NoV": _VIEW, "a": 0.25}),), "NoL"
    ),  # fmt: skip
    "diffuse": Sweep(
        "light angle θl (degrees)",
        "diffuse lobe",
        (("roughness 0.5", {"NoV": _VIEW, "phi": 0.0, "roughness": 0.5}),),
        "NoL",
    ),  # fmt: skip
    "specular": Sweep(
        "light angle θl (degrees)",
        "specular lobe",
        (("roughness 0.5", {"NoV": _VIEW, "phi": np.pi, "roughness": 0.5}),),
        "NoL",
        log=True,
    ),  # fmt: skip
}


@dataclass
class Curves:
    """A slot's curves: per panel, each variant's values and the reference's, over ANGLES."""

    slot: str
    reference_variant: str | None
    reference_name: str | None
    panels: list[tuple[str, dict[str, np.ndarray], np.ndarray | None]]


def _base(sweep: Sweep, fixed: dict[str, float]) -> dict[str, np.ndarray]:
    count = len(ANGLES)
    base = {key: np.full(count, value) for key, value in fixed.items()}
    base[sweep.swept] = _COS.copy()
    return base


def slot_curves(slot: str, ids: list[str], reference_variant: str | None) -> Curves | None:
    """Each variant of `slot` evaluated on the GPU along the slot's sweep, and the float64
    reference of `reference_variant`; None for a slot without a sweep or a variant that can be
    probed."""
    sweep = SWEEPS.get(slot)
    if sweep is None:
        return None
    catalog = load_catalog()
    reference = catalog.get(reference_variant) if reference_variant in ids else None
    panels = []
    for suffix, fixed in sweep.cases:
        base = _base(sweep, fixed)
        values: dict[str, np.ndarray] = {}
        for snippet_id in ids:
            snippet = catalog.get(snippet_id)
            try:
                out = run_probe(snippet_id, probe_arguments(snippet, base), catalog)
            except InputError:
                continue  # a variant that cannot be probed on its own: not on the chart
            values[snippet_id] = np.asarray(out if out.ndim == 1 else out[:, 0], np.float64)
        exact = None
        if reference is not None and reference.reference:
            ref = reference_values(reference, base)
            exact = ref if ref.ndim == 1 else ref[:, 0]
        panels.append((suffix, values, exact))
    if not any(values for _, values, _ in panels):
        return None
    name = reference.reference if reference is not None else None
    return Curves(slot, reference_variant if reference else None, name, panels)


def curves_png(curves: Curves, cache_dir: Path | None) -> bytes:
    """The chart of `curves`, from `cache_dir` where it holds it (keyed by the data)."""
    data = [
        [suffix, {k: v.round(6).tolist() for k, v in values.items()},
         None if exact is None else exact.round(6).tolist()]
        for suffix, values, exact in curves.panels
    ]  # fmt: skip
    key = hashlib.sha256(
        json.dumps([glint.__version__, CURVES_VERSION, curves.slot, data]).encode("utf-8")
    ).hexdigest()[:32]
    cached = cache_dir / f"curves-{key}.png" if cache_dir is not None else None
    if cached is not None and cached.is_file():
        return cached.read_bytes()
    png = _draw(curves)
    if cached is not None:
        cached.parent.mkdir(parents=True, exist_ok=True)
        write_atomic(cached, png)
    return png


def _draw(curves: Curves) -> bytes:
    sweep = SWEEPS[curves.slot]
    plt = pyplot()
    count = len(curves.panels)
    fig, axes = plt.subplots(1, count, figsize=(6.0 * count, 3.6), dpi=100, layout="constrained",
                             squeeze=False)  # fmt: skip
    for ax, (suffix, values, exact) in zip(axes[0], curves.panels, strict=True):
        for index, (snippet_id, ys) in enumerate(values.items()):
            ys = np.where(ys > 1e-4, ys, np.nan) if sweep.log else ys  # a line ends below
            ax.plot(ANGLES, ys, color=f"C{index % 10}", label=snippet_id.split(".", 1)[1])
        if exact is not None:
            ys = np.where(exact > 1e-4, exact, np.nan) if sweep.log else exact
            ax.plot(ANGLES, ys, "k--", linewidth=1.0, label=f"{curves.reference_name} (float64)")
        if sweep.log:
            ax.set_yscale("log")
        ax.set_xlabel(sweep.label)
        ax.set_ylabel(sweep.ylabel)
        ax.set_title(f"slot {curves.slot}, {suffix}", fontsize=9)
        ax.legend(fontsize=7)
    return figure_png(fig)


def curves_section(png_path: str, curves: Curves) -> str:
    """The Markdown of the chart on the slot's page (`png_path` relative to that page)."""
    truth = (f", and the float64 reference `{curves.reference_name}` of "
             f"`{curves.reference_variant}` (dashed)") if curves.reference_name else ""  # fmt: skip
    return (
        "## Curves\n\n"
        f"![every {curves.slot} variant along the sweep]({png_path})\n\n"
        f"Every variant evaluated on the GPU along {SWEEPS[curves.slot].label}{truth}: where "
        "the lines part is where the choice shows in a picture.\n\n"
    )
