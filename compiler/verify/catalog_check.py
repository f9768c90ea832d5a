"""The catalog check: each snippet's front matter agrees with its parsed body, and each snippet
compiles with glslang together with everything it requires.

What a body defines must be exactly what `provides` declares; what it uses from outside must be
declared in `requires` (a symbol, or a slot whose entry function it calls), and nothing required
may go unused. A variant of a slot must define the slot's entry with the slot's exact prototype.
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import Catalog, Snippet, load_catalog
from glint.compiler.catalog.slots import SCENE_SYMBOLS, SLOTS
from glint.compiler.compose.linking.standalone import standalone_source
from glint.compiler.glsl.symbols import ModuleSymbols, analyze
from glint.compiler.target.glslang import Diagnostic, validate
from glint.compiler.target.shadertoy import UNIFORM_NAMES


@dataclass
class Problem:
    snippet: str  # file of the snippet
    message: str

    def __str__(self) -> str:
        return f"{self.snippet}: {self.message}"


def snippet_symbols(snippet: Snippet) -> ModuleSymbols:
    """The parsed body, with line numbers of the snippet file."""
    source = f"#line {snippet.body_line}\n{snippet.body}"
    return analyze(source, snippet.relpath, provided=UNIFORM_NAMES)


def check_front_matter(snippet: Snippet, catalog: Catalog) -> list[Problem]:
    """Compare `provides`/`requires`/`params` with what the body defines and uses."""
    symbols = snippet_symbols(snippet)
    problems: list[str] = []
    declared = set(snippet.provides)
    for name in sorted(declared - symbols.defined):
        problems.append(f"provides '{name}', but the body does not define it")
    for name in sorted(symbols.defined - declared):
        problems.append(f"defines '{name}', which is not declared in provides")

    # What each requirement makes available: a symbol itself, or a slot's entry function.
    available: dict[str, str] = {}
    for req in snippet.requires:
        slot = SLOTS.get(req)
        if slot is not None and slot.entry:
            available[slot.entry] = req
        else:
            available[req] = req
        if req not in SLOTS and req not in SCENE_SYMBOLS and not catalog.providers(req):
            problems.append(f"requires '{req}', which no snippet provides and is not a slot")
    params = set(snippet.params)
    free = symbols.free - params
    for name in sorted(free - available.keys()):
        problems.append(f"uses '{name}', which is not declared in requires")
    used = {available[name] for name in free if name in available}
    for req in sorted(set(snippet.requires) - used):
        problems.append(f"requires '{req}', but the body never uses it")
    for name in sorted(params - symbols.free):
        problems.append(f"declares parameter '{name}', but the body never uses it")

    slot = SLOTS[snippet.slot]
    if slot.entry:
        entry = next((f for f in symbols.functions if f.name == slot.entry), None)
        if entry is None:
            problems.append(f"a {slot.name} variant must define `{slot.prototype}`")
        elif entry.prototype != slot.prototype:
            problems.append(
                f"entry `{entry.prototype}` must have the slot's prototype `{slot.prototype}`"
            )
    return [Problem(snippet.file, message) for message in problems]


def compile_alone(snippet: Snippet, catalog: Catalog) -> list[Diagnostic]:
    return validate(standalone_source(snippet, catalog), f"<{snippet.id} with its dependencies>")


def check_catalog(catalog: Catalog | None = None, compile: bool = True) -> list[str]:
    """Every problem of the catalog, as `file: message` lines (empty when it is sound)."""
    catalog = catalog or load_catalog()
    problems: list[str] = []
    for snippet in catalog.snippets.values():
        problems += [str(p) for p in check_front_matter(snippet, catalog)]
        if compile:
            problems += [str(d) for d in compile_alone(snippet, catalog) if d.severity == "error"]
    return problems
