"""A unit of emitted code: a catalog snippet or a piece generated from the scene."""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import Snippet

GENERATED = "<generated>"
CONSTANTS = "scene.constants"  # the scene's #define block (emitter.parameter_unit)


@dataclass(frozen=True)
class Unit:
    id: str  # snippet id ("D.ggx") or generated piece ("scene.map")
    slot: str  # the snippet's slot, or "scene"
    provides: tuple[str, ...]
    requires: tuple[str, ...]
    body: str
    origin: str  # file the body comes from, or GENERATED
    line: int  # line of `origin` where the body starts
    summary: str = ""
    # Where the unit goes among units that are ready at the same time (lower first); generated
    # units go after the snippets unless they say otherwise. Dependencies always come first.
    rank: int | None = None
    # For the scene's own code: the calls that its content decided, each with the reason
    # (("shadow", "lights[0] (directional) casts shadows"), ...), in the order the planner
    # reads them (compose/planning/scene_slots.py).
    why: tuple[tuple[str, str], ...] = ()


def from_snippet(snippet: Snippet) -> Unit:
    return Unit(
        id=snippet.id,
        slot=snippet.slot,
        provides=snippet.provides,
        requires=snippet.requires,
        body=snippet.body,
        origin=snippet.relpath,
        line=snippet.body_line,
        summary=snippet.summary,
    )


def generated(
    unit_id: str,
    provides: list[str],
    requires: list[str],
    body: str,
    rank: int | None = None,
    why: list[tuple[str, str]] | None = None,
) -> Unit:
    return Unit(
        id=unit_id,
        slot="scene",
        provides=tuple(provides),
        requires=tuple(sorted(set(requires))),
        body=body,
        origin=GENERATED,
        line=1,
        rank=rank,
        why=tuple(why or ()),
    )
