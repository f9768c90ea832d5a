"""The catalog as data: what `glint catalog --json` prints, a stable interface."""

from __future__ import annotations

from typing import Any

from glint.compiler.catalog.loader import Snippet, load_catalog
from glint.compiler.glsl.symbols import analyze
from glint.compiler.target.shadertoy import UNIFORM_NAMES


def signatures(snippet: Snippet) -> list[str]:
    """GLSL prototypes of the functions a snippet provides, as its parsed body defines them."""
    symbols = analyze(
        snippet.body, snippet.relpath, predefined=_param_defaults(snippet), provided=UNIFORM_NAMES
    )
    provided = set(snippet.provides)
    return [f.prototype for f in symbols.functions if f.name in provided]


def _param_defaults(snippet: Snippet) -> dict[str, str]:
    from glint.compiler.catalog.loader import glsl_value

    return {name: glsl_value(p.default, p.type) for name, p in snippet.params.items()}


def entry(snippet: Snippet) -> dict[str, Any]:
    return {
        "id": snippet.id,
        "slot": snippet.slot,
        "variant": snippet.variant,
        "summary": snippet.summary,
        "provides": list(snippet.provides),
        "requires": list(snippet.requires),
        "signature": signatures(snippet),
        "params": [
            {"name": p.name, "type": p.type, "default": p.default, "range": p.range}
            for p in snippet.params.values()
        ],
        "domain": snippet.domain,
        "reference": snippet.reference,
        "error_budget": snippet.error_budget,
        "cost": snippet.cost,
        "sources": list(snippet.sources),
        "file": snippet.file,
        "preset_of": snippet.preset_of,  # the base variant whose body a preset runs, or ""
    }


def catalog_entries() -> list[dict[str, Any]]:
    return [entry(s) for s in load_catalog().snippets.values()]
