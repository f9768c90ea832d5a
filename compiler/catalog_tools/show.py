"""`glint catalog show ID`: one snippet with everything it needs, as one block to paste.

The dependencies are resolved as `standalone` resolves them for the catalog check and the probes:
the snippet fills its own slot, every other slot takes its balanced-tier variant. What a scene
would generate is left out; the block declares the prototypes of the scene functions it calls
(`map`, ...) so that it compiles wherever the user defines them, and gives the scene constants it
uses (`SUN_DIR`, ...) stand-in values to edit.
"""

from __future__ import annotations

from glint.compiler.catalog.loader import Catalog, Snippet, glsl_value, load_catalog
from glint.compiler.catalog.slots import SCENE_FUNCTIONS, SCENE_SYMBOLS, SLOTS
from glint.compiler.compose.linking.resolver import resolve
from glint.compiler.compose.linking.standalone import SCENE_DEFINES, standalone_choices
from glint.compiler.compose.units import Unit, from_snippet, generated

_SCENE_UNIT = "scene.provided"


def show_source(snippet_id: str, catalog: Catalog | None = None) -> str:
    """The snippet and its dependencies in dependency order, each once, with a header naming
    them, the parameters as #defines and the scene's functions as prototypes."""
    catalog = catalog or load_catalog()
    snippet = catalog.get(snippet_id)  # InputError naming close matches for an unknown id
    choices = standalone_choices(snippet)
    scene_symbols = sorted(set(SCENE_SYMBOLS) | set(SCENE_DEFINES))
    # A placeholder stands for the scene so that requirements on it resolve; it is not printed.
    scene = generated(_SCENE_UNIT, scene_symbols, [], "")
    units = resolve([scene, from_snippet(snippet)], catalog, choices)
    used = {req for u in units for req in u.requires}
    units = [u for u in units if u.id != _SCENE_UNIT]
    needed = [name for name in scene_symbols if name in used]
    parts = [
        _header(snippet, units, catalog, choices, needed),
        _defines(units, catalog, needed),
        _prototypes(needed),
    ]
    parts += [_body(u) for u in units]
    return "\n".join(part for part in parts if part)


def _header(
    snippet: Snippet,
    units: list[Unit],
    catalog: Catalog,
    choices: dict[str, str],
    needed: list[str],
) -> str:
    width = max(len(u.id) for u in units)
    lines = [
        f"// glint catalog show {snippet.id}: {snippet.summary}",
        f"// {snippet.file or snippet.relpath} and what it needs, in dependency order;",
        "// other slots take their balanced-tier variants:",
    ]
    for unit in units:
        if unit.id == snippet.id:
            why = "the snippet shown"
        elif unit.slot in SLOTS and not SLOTS[unit.slot].many and choices.get(unit.slot):
            why = f"slot {unit.slot}, balanced tier"
        else:
            why = "library"
        lines.append(f"//   {unit.id.ljust(width)}  {catalog.snippets[unit.id].summary} ({why})")
    functions = [SCENE_FUNCTIONS[n] for n in needed if n in SCENE_FUNCTIONS]
    constants = [n for n in needed if n not in SCENE_FUNCTIONS]
    if functions:
        lines.append(f"// Define in your shader (declared below): {'; '.join(functions)}")
    if constants:
        lines.append(f"// Scene constants with stand-in values to edit: {', '.join(constants)}")
    return "\n".join(lines) + "\n"


def _defines(units: list[Unit], catalog: Catalog, needed: list[str]) -> str:
    knobs: dict[str, str] = {n: SCENE_DEFINES[n] for n in needed if n in SCENE_DEFINES}
    for unit in units:
        for name, param in catalog.snippets[unit.id].params.items():
            knobs.setdefault(name, glsl_value(param.default, param.type))
    if not knobs:
        return ""
    lines = ["// Parameters (defaults; edit to taste)."]
    lines += [f"#define {name} {value}" for name, value in knobs.items()]
    return "\n".join(lines) + "\n"


def _prototypes(needed: list[str]) -> str:
    functions = [SCENE_FUNCTIONS[n] for n in needed if n in SCENE_FUNCTIONS]
    if not functions:
        return ""
    return "// Provided by your scene.\n" + "".join(f"{f};\n" for f in functions)


def _body(unit: Unit) -> str:
    return f"// {unit.id} ({unit.origin})\n{unit.body.strip(chr(10))}\n"
