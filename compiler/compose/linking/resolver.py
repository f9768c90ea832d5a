"""The resolver: from the units the scene needs to every unit they reach, in dependency order.

A requirement names a symbol ("PI", "map") or a one-variant slot ("D"). A slot resolves to the
variant the plan chose; a symbol to the unit that provides it, looked up first among the units
already taken, then in the catalog (a library snippet, or the chosen variant of a slot). Each unit
is emitted once, after everything it requires. A cycle, a requirement nothing provides, or two
units providing one symbol is an error that names the units involved.
"""

from __future__ import annotations

import heapq
from collections.abc import Collection, Sequence

from glint.compiler.catalog.loader import Catalog, Snippet
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.compose.units import CONSTANTS, Unit, from_snippet
from glint.compiler.errors import InputError

# Emission order among units that are ready at the same time: by slot, so output reads top-down
# from constants and primitives to lights and the main function.
_SLOT_RANK = {name: i for i, name in enumerate(SLOTS)}


def resolve(
    roots: list[Unit],
    catalog: Catalog,
    choices: dict[str, str],
    constants: Collection[str] = (),
) -> list[Unit]:
    """All units reachable from `roots`, each once, every unit after those it requires.
    `constants` are the names the scene's #define block gives (SUN_DIR): it comes before every
    unit (emitter.parameter_unit), so they need no unit here."""
    units: dict[str, Unit] = {}
    order: list[str] = []
    pending = list(roots)
    while pending:
        unit = pending.pop(0)
        if unit.id in units:
            continue
        units[unit.id] = unit
        order.append(unit.id)
        for req in unit.requires:
            if req in constants:
                continue
            provider = _provider(req, unit, units, catalog, choices, roots)
            if provider.id not in units:
                pending.append(provider)
    _check_unique(units, constants)
    edges = {uid: _dependencies(units[uid], units, catalog, choices, constants) for uid in order}
    return [units[uid] for uid in _topological(order, edges, units)]


def providers(
    symbol: str, catalog: Catalog, choices: dict[str, str]
) -> tuple[list[Snippet], list[Snippet]]:
    """The catalog snippets that may provide `symbol` to a shader of this plan: library
    snippets (of many-variant slots, all usable at once), and the chosen variants of one-variant
    slots (the others are not in the shader)."""
    candidates = catalog.providers(symbol)
    library = [s for s in candidates if SLOTS[s.slot].many]
    chosen = [s for s in candidates if not SLOTS[s.slot].many and choices.get(s.slot) == s.id]
    return library, chosen


def _provider(
    req: str,
    unit: Unit,
    taken: dict[str, Unit],
    catalog: Catalog,
    choices: dict[str, str],
    given: Sequence[Unit] = (),
) -> Unit:
    if req in SLOTS and not SLOTS[req].many:
        if req not in choices:
            raise InputError(f"{unit.id} requires slot {req}, but the plan has no variant for it")
        return from_snippet(catalog.get(choices[req]))
    for other in [*taken.values(), *given]:  # the scene's own units (the user's file) first
        if req in other.provides:
            return other
    library, chosen = providers(req, catalog, choices)
    found = library + chosen
    if len(found) == 1:
        return from_snippet(found[0])
    if not found:
        unchosen = ", ".join(s.id for s in catalog.providers(req))
        hint = f" (provided by {unchosen}, which the plan did not choose)" if unchosen else ""
        raise InputError(f"{unit.id} requires '{req}', which no unit provides{hint}")
    names = " and ".join(s.id for s in found)
    raise InputError(f"'{req}' required by {unit.id} is provided by both {names}")


def _dependencies(
    unit: Unit,
    units: dict[str, Unit],
    catalog: Catalog,
    choices: dict[str, str],
    constants: Collection[str],
) -> set[str]:
    found = {
        _provider(req, unit, units, catalog, choices).id
        for req in unit.requires
        if req not in constants
    }
    return found - {unit.id}


def _check_unique(units: dict[str, Unit], constants: Collection[str]) -> None:
    owner: dict[str, str] = dict.fromkeys(constants, CONSTANTS)
    for unit in units.values():
        for symbol in unit.provides:
            if symbol in owner:
                raise InputError(
                    f"'{symbol}' is provided by both {owner[symbol]} and {unit.id}; "
                    "keep one of them"
                )
            owner[symbol] = unit.id


def _rank(unit: Unit, index: int) -> tuple[int, str, int]:
    rank = unit.rank if unit.rank is not None else _SLOT_RANK.get(unit.slot, len(_SLOT_RANK))
    return (rank, unit.id, index)


def _topological(order: list[str], edges: dict[str, set[str]], units: dict[str, Unit]) -> list[str]:
    """Kahn's algorithm; among ready units the lowest slot rank goes first (deterministic)."""
    waiting = {uid: set(deps) for uid, deps in edges.items()}
    dependents: dict[str, list[str]] = {uid: [] for uid in order}
    for uid, deps in edges.items():
        for dep in deps:
            dependents[dep].append(uid)
    ready = [_rank(units[uid], i) + (uid,) for i, uid in enumerate(order) if not waiting[uid]]
    heapq.heapify(ready)
    out: list[str] = []
    while ready:
        uid = heapq.heappop(ready)[-1]
        out.append(uid)
        for dependent in dependents[uid]:
            waiting[dependent].discard(uid)
            if not waiting[dependent]:
                rank = _rank(units[dependent], order.index(dependent))
                heapq.heappush(ready, rank + (dependent,))
    if len(out) < len(order):
        raise InputError("dependency cycle: " + _find_cycle(waiting))
    return out


def _find_cycle(waiting: dict[str, set[str]]) -> str:
    """Follow unmet dependencies from a stuck unit until one repeats: that loop is the cycle."""
    start = next(uid for uid, deps in waiting.items() if deps)
    path = [start]
    while True:
        nxt = sorted(waiting[path[-1]])[0]
        if nxt in path:
            loop = path[path.index(nxt) :] + [nxt]
            return " -> ".join(loop)
        path.append(nxt)
