"""Loading the snippet catalog: one GLSL file per variant, TOML front matter in a block comment.

A snippet file opens with

    /* ---
    id = "D.ggx"
    slot = "D"
    ...
    --- */

followed by the GLSL body. This module reads and checks the front matter; what the body defines
and calls is checked against it in `catalog_check`.

A preset is a variant that is another one with different parameter defaults (the soft shadow at
12 steps): its front matter names the base with `preset_of`, gives the new defaults in `params`
(`params = { SHADOW_STEPS = 12 }`), and it has no body. The loader takes the body, `provides`,
`requires`, `sources`, `reference` and `domain` from the base, so one GLSL body serves every step
count; a preset names its own `error_budget` and `cost` where they differ.
"""

from __future__ import annotations

import difflib
import tomllib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from functools import cache
from importlib import resources
from pathlib import Path
from typing import Any

from glint.compiler.catalog.slots import SLOTS
from glint.compiler.errors import InputError

OPEN = "/* ---"
CLOSE = "--- */"
REQUIRED_KEYS = {"id", "slot", "summary", "provides", "requires", "sources"}
# `formula`: the model in LaTeX, for the docs site's page of the variant (glint.compiler.site).
# `distance`: for a signed-distance snippet, "exact" (the Euclidean distance) or "bound" (a lower
# bound of it, zero on the surface: safe to march; an over-relaxing marcher must keep its
# overlap test, as raymarch.relaxed does, and fails more steps on it).
# `budget_why`: why `error_budget` is what it is (the error the model makes by design, what was
# measured and on what), shown beside the budget on the variant's page.
OPTIONAL_KEYS = {
    "params", "domain", "reference", "error_budget", "budget_why", "cost", "formula", "distance"
}  # fmt: skip
DISTANCE_KINDS = ("exact", "bound")
# A preset takes its code and its contract from its base; it may add sources of its own.
PRESET_REQUIRED_KEYS = {"id", "slot", "summary", "preset_of", "params"}
PRESET_OPTIONAL_KEYS = {"sources", "domain", "reference", "error_budget", "budget_why", "cost"}
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
    budget_why: str  # why the budget is what it is ("" where none is given)
    cost: str
    relpath: str  # e.g. "snippets/D/ggx.glsl": the file of the body, how errors name it
    body: str  # the GLSL after the front matter
    body_line: int  # line of `relpath` on which the body starts (1-based)
    preset_of: str = ""  # id of the base variant when this is a preset, else ""
    file: str = ""  # the snippet's own file: `relpath`, except for a preset
    formula: str = ""  # the model in LaTeX (a preset's own file has none)
    # "exact": returns the Euclidean signed distance; "bound": a lower bound of its magnitude
    # with the right sign, zero on the surface (sphere tracing stays safe, and over-relaxation
    # with the overlap test of raymarch.relaxed; without it a relaxed step could tunnel).
    distance: str = "exact"

    def __post_init__(self) -> None:
        if not self.file:
            object.__setattr__(self, "file", self.relpath)

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

    def params_of(self, ids: Iterable[str]) -> dict[str, Param]:
        """The parameters of the snippets among `ids` (others, generated code, are skipped),
        in order; a name two snippets share is the first one's."""
        params: dict[str, Param] = {}
        for snippet_id in ids:
            snippet = self.snippets.get(snippet_id)
            for name, param in snippet.params.items() if snippet else ():
                params.setdefault(name, param)
        return params

    def in_slot(self, slot: str) -> list[Snippet]:
        return [s for s in self.snippets.values() if s.slot == slot]

    def providers(self, symbol: str) -> list[Snippet]:
        return [s for s in self.snippets.values() if symbol in s.provides]


def snippets_root() -> Path:
    """The folder of the installed `glint.snippets` package."""
    return Path(str(resources.files("glint.snippets")))


def read_front_matter(text: str, relpath: str) -> tuple[dict[str, Any], str, int]:
    """The TOML front matter of a snippet file, the body after it and the body's first line."""
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
    return meta, "\n".join(lines[end + 1 :]) + "\n", end + 2


def parse_snippet(text: str, relpath: str, bases: Mapping[str, Snippet] | None = None) -> Snippet:
    """Read one snippet file; front-matter problems name the file and line. A preset
    (`preset_of`) is completed from its base, looked up in `bases`."""
    meta, body, body_line = read_front_matter(text, relpath)
    if "preset_of" in meta:
        return _preset(meta, body, relpath, bases or {})
    _check_keys(meta, relpath, REQUIRED_KEYS, OPTIONAL_KEYS)
    _check_id(meta, relpath)
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
        budget_why=str(meta.get("budget_why", "")),
        cost=meta.get("cost", ""),
        relpath=relpath,
        body=body,
        body_line=body_line,
        formula=str(meta.get("formula", "")),
        distance=_distance(meta, relpath),
    )


def is_preset(text: str) -> bool:
    """Whether a snippet file's front matter makes it a preset (without checking the rest)."""
    try:
        return "preset_of" in read_front_matter(text, "<snippet>")[0]
    except InputError:
        return False


def _check_id(meta: dict[str, Any], relpath: str) -> None:
    slot_dir = Path(relpath).parent.name
    stem = Path(relpath).stem
    if meta["slot"] != slot_dir or meta["id"] != f"{slot_dir}.{stem}":
        raise InputError(
            f"{relpath}: id '{meta['id']}' and slot '{meta['slot']}' must be "
            f"'{slot_dir}.{stem}' and '{slot_dir}' (the folder is the slot, the file the variant)"
        )
    if meta["slot"] not in SLOTS:
        raise InputError(f"{relpath}: unknown slot '{meta['slot']}'; slots: {', '.join(SLOTS)}")


def _preset(meta: dict[str, Any], body: str, relpath: str, bases: Mapping[str, Snippet]) -> Snippet:
    _check_keys(meta, relpath, PRESET_REQUIRED_KEYS, PRESET_OPTIONAL_KEYS)
    _check_id(meta, relpath)
    if body.strip():
        raise InputError(f"{relpath}: a preset has no GLSL body (it runs its base's)")
    base_id = meta["preset_of"]
    base = bases.get(base_id) if isinstance(base_id, str) else None
    if base is None:
        known = ", ".join(sorted(s.id for s in bases.values() if s.slot == meta["slot"]))
        raise InputError(
            f"{relpath}: preset_of {base_id!r} is not a variant with a body; "
            f"variants of {meta['slot']}: {known or 'none'}"
        )
    if base.preset_of:
        raise InputError(f"{relpath}: preset_of '{base_id}' is itself a preset; name its base")
    if base.slot != meta["slot"]:
        raise InputError(f"{relpath}: preset_of '{base_id}' is in slot {base.slot}, not here")
    sources = meta.get("sources", [])
    if not isinstance(sources, list) or not all(isinstance(v, str) for v in sources):
        raise InputError(f"{relpath}: 'sources' must be a list of strings")
    return replace(
        base,
        id=meta["id"],
        summary=meta["summary"],
        sources=base.sources + tuple(s for s in sources if s not in base.sources),
        params=_preset_params(meta["params"], base, relpath),
        domain=dict(meta.get("domain", base.domain)),
        reference=meta.get("reference", base.reference),
        error_budget=dict(meta.get("error_budget", base.error_budget)),
        # the base's reason goes with the base's budget, not with one the preset sets
        budget_why=str(meta.get("budget_why", "" if "error_budget" in meta else base.budget_why)),
        cost=meta.get("cost", ""),
        preset_of=base.id,
        file=relpath,
        formula="",
    )


def _preset_params(raw: Any, base: Snippet, relpath: str) -> dict[str, Param]:
    """The base's parameters with the defaults the preset sets (`NAME = value`)."""
    if not isinstance(raw, dict) or not raw:
        raise InputError(f"{relpath}: a preset's params must set at least one of its base's")
    params = dict(base.params)
    for name, value in raw.items():
        if name not in base.params:
            known = ", ".join(base.params) or "none"
            raise InputError(
                f"{relpath}: param '{name}' is not a parameter of {base.id} (it has: {known})"
            )
        param = base.params[name]
        if not _fits(value, param):
            raise InputError(
                f"{relpath}: param '{name}' = {value!r} is not a {param.type}"
                + (f" in {list(param.range)}" if param.range else "")
            )
        params[name] = replace(param, default=value)
    return params


def _fits(value: Any, param: Param) -> bool:
    """Whether `value` is of the parameter's type and inside its range."""
    if param.type == "bool":
        return isinstance(value, bool)
    if param.type == "vec3":
        return isinstance(value, list) and len(value) == 3 and all(_number(v) for v in value)
    if not _number(value) or (param.type == "int" and not isinstance(value, int)):
        return False
    return param.range is None or param.range[0] <= value <= param.range[1]


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _check_keys(meta: dict[str, Any], relpath: str, required: set[str], optional: set[str]) -> None:
    missing = required - meta.keys()
    unknown = meta.keys() - required - optional
    what = "a preset's front matter" if "preset_of" in required else "front matter"
    if missing:
        raise InputError(f"{relpath}: {what} lacks {', '.join(sorted(missing))}")
    if unknown:
        allowed = ", ".join(sorted(required | optional))
        raise InputError(
            f"{relpath}: unknown front-matter key {sorted(unknown)}; allowed: {allowed}"
        )
    for key in ("provides", "requires", "sources"):
        if key not in required:
            continue
        if not isinstance(meta[key], list) or not all(isinstance(v, str) for v in meta[key]):
            raise InputError(f"{relpath}: '{key}' must be a list of strings")


def _distance(meta: dict[str, Any], relpath: str) -> str:
    value = meta.get("distance", "exact")
    if value not in DISTANCE_KINDS:
        raise InputError(
            f"{relpath}: distance = {value!r}; expected one of {', '.join(DISTANCE_KINDS)}"
        )
    return value


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
    """Every `snippets/<slot>/<variant>.glsl` under `root` (default: the installed catalog).
    `snippets/scenes/` holds example scenes, whose GLSL files are users' geometry, not
    snippets."""
    root = root or snippets_root()
    catalog = Catalog()
    texts = {
        f"snippets/{path.parent.name}/{path.name}": path.read_text(encoding="utf-8")
        for path in sorted(root.glob("*/*.glsl"))
        if path.parent.name != "scenes"
    }
    # Presets after every variant with a body, so that their bases are there to complete them.
    ordered = sorted(texts, key=lambda relpath: is_preset(texts[relpath]))
    for relpath in ordered:
        snippet = parse_snippet(texts[relpath], relpath, catalog.snippets)
        catalog.snippets[snippet.id] = snippet
    # Listings show the catalog in file order, presets among the others.
    in_file_order = sorted(catalog.snippets.values(), key=lambda s: Path(s.file))
    return Catalog({s.id: s for s in in_file_order})


def glsl_value(value: Any, type_: str) -> str:
    """A Python value as GLSL source of the given type: 3 -> 3.0 for float, lists -> vec3(...)."""
    if type_ == "float":
        return glsl_float(value)
    if type_ == "int":
        return str(int(value))
    if type_ == "bool":
        return "true" if value else "false"
    if type_ in ("vec2", "vec3"):
        return f"{type_}(" + ", ".join(glsl_float(v) for v in value) + ")"
    raise ValueError(f"unknown parameter type {type_}")


def glsl_float(x: float) -> str:
    """Shortest round-tripping decimal with a decimal point, as GLSL wants for a float."""
    text = repr(float(x))
    return text if any(c in text for c in ".en") else text + ".0"
