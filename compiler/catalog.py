"""Loading the snippet catalog: one GLSL file per variant, TOML front matter in a block comment.

A snippet file opens with

    /* ---
    id = "D.ggx"
    slot = "D"
    ...
    --- */

followed by the GLSL body. This module reads and checks the front matter; what the body defines
and calls is checked against it in `catalog_check`.
"""

from __future__ import annotations

import difflib
import tomllib
from dataclasses import dataclass, field
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

from .errors import InputError
from .slots import SLOTS

OPEN = "/* ---"
CLOSE = "--- */"
REQUIRED_KEYS = {"id", "slot", "summary", "provides", "requires", "sources"}
OPTIONAL_KEYS = {"params", "domain", "reference", "error_budget", "cost"}
PARAM_TYPES = {"float", "int", "bool", "vec3"}


@dataclass(frozen=True)
class Param:
    """A `#define` knob of a snippet; the composer writes its value in the parameter block."""

    name: str
    type: str
    default: Any
    range: tuple[float, float] | None = None


@dataclass(frozen=True)
class Snippet:
    id: str
    slot: str
    summary: str
    provides: tuple[str, ...]
    requires: tuple[str, ...]
    sources: tuple[str, ...]
    params: dict[str, Param]
    domain: dict[str, Any]
    reference: str
    error_budget: dict[str, float]  # bounds of the error against `reference`, e.g. max_abs
    cost: str
    relpath: str  # e.g. "snippets/D/ggx.glsl": how errors and headers name the file
    body: str  # the GLSL after the front matter
    body_line: int  # line of the file on which the body starts (1-based)

    @property
    def variant(self) -> str:
        return self.id.split(".", 1)[1]


@dataclass
class Catalog:
    snippets: dict[str, Snippet] = field(default_factory=dict)

    def get(self, snippet_id: str) -> Snippet:
        if snippet_id in self.snippets:
            return self.snippets[snippet_id]
        close = difflib.get_close_matches(snippet_id, self.snippets, n=3)
        hint = f"; did you mean {', '.join(close)}?" if close else "; see `glint catalog`"
        raise InputError(f"unknown snippet '{snippet_id}'{hint}")

    def in_slot(self, slot: str) -> list[Snippet]:
        return [s for s in self.snippets.values() if s.slot == slot]

    def providers(self, symbol: str) -> list[Snippet]:
        return [s for s in self.snippets.values() if symbol in s.provides]


def snippets_root() -> Path:
    """The folder of the installed `glint.snippets` package."""
    return Path(str(resources.files("glint.snippets")))


def parse_snippet(text: str, relpath: str) -> Snippet:
    """Read one snippet file; front-matter problems name the file and line."""
    lines = text.splitlines()
    if not lines or lines[0].strip() != OPEN:
        raise InputError(f"{relpath}:1: a snippet must open with '{OPEN}' front matter")
    try:
        end = next(i for i, line in enumerate(lines) if line.strip() == CLOSE)
    except StopIteration:
        raise InputError(f"{relpath}:1: front matter is not closed by '{CLOSE}'") from None
    try:
        meta = tomllib.loads("\n".join(lines[1:end]))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{relpath}: front matter is not valid TOML: {exc}") from None
    _check_keys(meta, relpath)
    slot_dir = Path(relpath).parent.name
    stem = Path(relpath).stem
    if meta["slot"] != slot_dir or meta["id"] != f"{slot_dir}.{stem}":
        raise InputError(
            f"{relpath}: id '{meta['id']}' and slot '{meta['slot']}' must be "
            f"'{slot_dir}.{stem}' and '{slot_dir}' (the folder is the slot, the file the variant)"
        )
    if meta["slot"] not in SLOTS:
        raise InputError(f"{relpath}: unknown slot '{meta['slot']}'; slots: {', '.join(SLOTS)}")
    return Snippet(
        id=meta["id"],
        slot=meta["slot"],
        summary=meta["summary"],
        provides=tuple(meta["provides"]),
        requires=tuple(meta["requires"]),
        sources=tuple(meta["sources"]),
        params=_params(meta.get("params", {}), relpath),
        domain=dict(meta.get("domain", {})),
        reference=meta.get("reference", ""),
        error_budget=dict(meta.get("error_budget", {})),
        cost=meta.get("cost", ""),
        relpath=relpath,
        body="\n".join(lines[end + 1 :]) + "\n",
        body_line=end + 2,
    )


def _check_keys(meta: dict[str, Any], relpath: str) -> None:
    missing = REQUIRED_KEYS - meta.keys()
    unknown = meta.keys() - REQUIRED_KEYS - OPTIONAL_KEYS
    if missing:
        raise InputError(f"{relpath}: front matter lacks {', '.join(sorted(missing))}")
    if unknown:
        allowed = ", ".join(sorted(REQUIRED_KEYS | OPTIONAL_KEYS))
        raise InputError(
            f"{relpath}: unknown front-matter key {sorted(unknown)}; allowed: {allowed}"
        )
    for key in ("provides", "requires", "sources"):
        if not isinstance(meta[key], list) or not all(isinstance(v, str) for v in meta[key]):
            raise InputError(f"{relpath}: '{key}' must be a list of strings")


def _params(raw: dict[str, Any], relpath: str) -> dict[str, Param]:
    params = {}
    for name, spec in raw.items():
        typed = isinstance(spec, dict) and spec.get("type") in PARAM_TYPES
        if not typed or "default" not in spec:
            raise InputError(
                f"{relpath}: param '{name}' needs a type ({', '.join(sorted(PARAM_TYPES))}) "
                "and a default"
            )
        rng = spec.get("range")
        params[name] = Param(name, spec["type"], spec["default"], tuple(rng) if rng else None)
    return params


@cache
def load_catalog(root: Path | None = None) -> Catalog:
    """Every `snippets/<slot>/<variant>.glsl` under `root` (default: the installed catalog)."""
    root = root or snippets_root()
    catalog = Catalog()
    for path in sorted(root.glob("*/*.glsl")):
        relpath = f"snippets/{path.parent.name}/{path.name}"
        snippet = parse_snippet(path.read_text(encoding="utf-8"), relpath)
        catalog.snippets[snippet.id] = snippet
    return catalog


def glsl_value(value: Any, type_: str) -> str:
    """A Python value as GLSL source of the given type: 3 -> 3.0 for float, lists -> vec3(...)."""
    if type_ == "float":
        return glsl_float(value)
    if type_ == "int":
        return str(int(value))
    if type_ == "bool":
        return "true" if value else "false"
    if type_ == "vec3":
        return "vec3(" + ", ".join(glsl_float(v) for v in value) + ")"
    raise ValueError(f"unknown parameter type {type_}")


def glsl_float(x: float) -> str:
    """Shortest round-tripping decimal with a decimal point, as GLSL wants for a float."""
    text = repr(float(x))
    return text if any(c in text for c in ".en") else text + ".0"
