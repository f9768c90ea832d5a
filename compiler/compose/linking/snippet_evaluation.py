"""Catalog snippets with their dependencies, evaluated by their slot's entry function."""

from __future__ import annotations

from typing import Any

import numpy as np

from glint.compiler.catalog.loader import Catalog, Snippet, glsl_value, load_catalog
from glint.compiler.catalog.slots import SCENE_SYMBOLS, SLOTS
from glint.compiler.compose.linking.resolver import resolve
from glint.compiler.compose.linking.standalone import standalone_choices
from glint.compiler.compose.units import from_snippet, generated
from glint.compiler.evaluator.api import evaluate

# GLSL types of the scene's symbols, from their descriptions in slots.SCENE_SYMBOLS
# ("vec3 unit direction towards the sun" -> vec3): externals standing in for them get these.
SCENE_TYPES: dict[str, str] = {
    name: text.split()[0]
    for name, text in SCENE_SYMBOLS.items()
    if text.split()[0] in ("float", "int", "vec3", "vec2", "vec4", "bool")
}


def snippet_units(snippet_id: str, catalog: Catalog | None = None) -> list[Snippet]:
    """The snippet and everything it requires, dependencies first, resolved as the composer
    does; the scene's own symbols (`map`, `SUN_DIR`) come from `externals` instead."""
    catalog = catalog or load_catalog()
    root = catalog.get(snippet_id)
    scene = generated("scene.externals", list(SCENE_SYMBOLS), [], "")
    units = resolve([scene, from_snippet(root)], catalog, standalone_choices(root))
    return [catalog.snippets[u.id] for u in units if u.id in catalog.snippets]


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
        external_types=SCENE_TYPES,
    )
