"""Catalog snippets with their dependencies, evaluated by their slot's entry function."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..catalog import Catalog, Snippet, glsl_value, load_catalog
from ..planner import tier_table
from ..slots import SLOTS
from .api import evaluate


def _provider(req: str, catalog: Catalog, chosen: dict[str, str]) -> Snippet | None:
    """The snippet a requirement resolves to, as the balanced tier would choose it; None for
    the scene's own symbols (`map`, `SUN_DIR`), which come from externals."""
    if req in SLOTS:
        variant = chosen.get(req)
        if variant is not None:
            return catalog.get(f"{req}.{variant}")
        options = catalog.in_slot(req)
        return options[0] if options else None
    providers = catalog.providers(req)
    if not providers:
        return None
    preferred = [p for p in providers if chosen.get(p.slot) == p.variant]
    return (preferred or sorted(providers, key=lambda p: p.id))[0]


def snippet_units(snippet_id: str, catalog: Catalog | None = None) -> list[Snippet]:
    """The snippet and everything it requires, dependencies first."""
    catalog = catalog or load_catalog()
    chosen = dict(tier_table()["balanced"])
    root = catalog.get(snippet_id)
    if not SLOTS[root.slot].many:
        chosen[root.slot] = root.variant  # the snippet itself fills its slot
    order: list[Snippet] = []
    seen: set[str] = set()

    def visit(snippet: Snippet) -> None:
        if snippet.id in seen:
            return
        seen.add(snippet.id)
        for req in snippet.requires:
            dep = _provider(req, catalog, chosen)
            if dep is not None:
                visit(dep)
        order.append(snippet)

    visit(root)
    return order


def snippet_source(snippet_id: str, catalog: Catalog | None = None) -> tuple[str, dict[str, str]]:
    """GLSL of the snippet with its dependencies (`#line` keeps errors at the snippet files),
    and the parameter defaults to predefine."""
    units = snippet_units(snippet_id, catalog)
    parts = [f'#line {s.body_line} "{s.relpath}"\n{s.body}' for s in units]
    predefined = {
        name: glsl_value(p.default, p.type) for s in units for name, p in s.params.items()
    }
    return "\n".join(parts), predefined


def entry_of(snippet_id: str, catalog: Catalog | None = None) -> str:
    snippet = (catalog or load_catalog()).get(snippet_id)
    entry = SLOTS[snippet.slot].entry
    if entry is None:
        raise ValueError(f"{snippet_id}: slot '{snippet.slot}' has no entry; name a function")
    return entry


def evaluate_snippet(
    snippet_id: str,
    function: str | None = None,
    args: dict[str, Any] | list[Any] | None = None,
    dtype: Any = np.float32,
    externals: dict[str, Any] | None = None,
    params: dict[str, str] | None = None,
) -> Any:
    """Evaluate a catalog snippet's function (its slot's entry by default) over lanes.
    `params` overrides parameter defaults (GLSL text, as for #define)."""
    catalog = load_catalog()
    source, predefined = snippet_source(snippet_id, catalog)
    predefined |= params or {}
    name = function or entry_of(snippet_id, catalog)
    return evaluate(
        source,
        name,
        args or [],
        dtype=dtype,
        predefined=predefined,
        filename=f"<{snippet_id}>",
        externals=externals,
    )
