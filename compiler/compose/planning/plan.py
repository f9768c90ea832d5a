"""The plan of a composition, the planner's result (planner.py) and what every later step reads
(baking, the emitter, the split, --explain): data only, so that those steps do not depend on
how the plan was made, nor on the scene's code generation that the planner runs."""

from __future__ import annotations

from dataclasses import dataclass, field

from glint.compiler.compose.planning.scene_slots import SlotUse


@dataclass
class Plan:
    tier: str
    choices: dict[str, str] = field(default_factory=dict)  # slot in use -> snippet id
    reasons: dict[str, str] = field(default_factory=dict)  # slot -> why that variant
    params: dict[str, str] = field(default_factory=dict)  # #define name -> GLSL value
    uses: dict[str, SlotUse] = field(default_factory=dict)  # every slot: in or out, and why
