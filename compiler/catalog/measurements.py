"""The measured cost and error of each variant, as `glint bench --update` last wrote them into
`snippets/measurements.json`, with the machine they came from. Never edited by hand: the
planner's `--budget` reads it, the bench regenerates it."""

from __future__ import annotations

import json
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from glint.compiler.errors import InputError

FILENAME = "measurements.json"


@dataclass(frozen=True)
class VariantCost:
    id: str
    slot: str
    reference: str | None  # what its error was measured against
    rms: float | None  # RMS error over the reference's domain; None: nothing to compare with
    gpu_ns: float  # measured ns per evaluation on `Measurements.machine`
    spirv: int  # SPIR-V instructions after spirv-opt -O
    pareto: bool


@dataclass(frozen=True)
class Measurements:
    machine: dict[str, Any]
    variants: dict[str, VariantCost]


def measurements_path() -> Path:
    return Path(str(resources.files("glint.snippets") / FILENAME))


def load_measurements(path: Path | None = None) -> Measurements:
    path = path or measurements_path()
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        variants = {
            key: VariantCost(
                id=key,
                slot=row["slot"],
                reference=row["reference"],
                rms=row["rms"],
                gpu_ns=float(row["gpu_ns"]),
                spirv=int(row["spirv"]),
                pareto=bool(row["pareto"]),
            )
            for key, row in data["variants"].items()
        }
        return Measurements(machine=data["machine"], variants=variants)
    except FileNotFoundError:
        raise InputError(
            f"{path}: no measurements yet; run `glint bench --update` to measure the variants"
        ) from None
    except (ValueError, KeyError, TypeError) as exc:
        raise InputError(
            f"{path}: unreadable measurements ({type(exc).__name__}: {exc}); "
            "regenerate it with `glint bench --update`"
        ) from None
