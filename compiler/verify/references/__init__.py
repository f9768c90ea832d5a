"""Float64 numpy references of the exact models the catalog's variants implement or approximate.

A snippet names its reference in front matter (`reference = "D_ggx"`); the probes evaluate the
GLSL on a grid of its `domain` and compare with `reference(name)(**inputs)`. Every reference
takes its inputs by keyword, named like the GLSL entry's parameters (V takes the `Dots` fields
NoL, NoV, NoH, VoH, LoV and a), and broadcasts them as numpy does.

Each module of this package contributes a `REFERENCES` dict (name -> function); the registry is
their union, so adding a family of references is adding one module.
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Callable

import numpy as np


def _collect() -> dict[str, Callable[..., np.ndarray]]:
    found: dict[str, Callable[..., np.ndarray]] = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        module = importlib.import_module(f"{__name__}.{info.name}")
        for name, function in getattr(module, "REFERENCES", {}).items():
            if name in found:
                raise RuntimeError(f"reference '{name}' defined twice (in {info.name})")
            found[name] = function
    return found


REFERENCES: dict[str, Callable[..., np.ndarray]] = _collect()


def reference(name: str) -> Callable[..., np.ndarray]:
    """The reference called `name`; KeyError naming the known ones otherwise."""
    try:
        return REFERENCES[name]
    except KeyError:
        known = ", ".join(sorted(REFERENCES))
        raise KeyError(f"unknown reference '{name}'; known: {known}") from None
