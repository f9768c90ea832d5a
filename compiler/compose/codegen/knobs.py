"""A value a page can set live through a uniform: the entry of a shader's parameter manifest
(uniform_params.py) for a snippet parameter or one of the scene's own values (scene_code.py).
Its own module, with no imports of the composer's, so that both can name it."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class UniformParam:
    """One manifest entry: a parameter the page sets through a uniform. A vec3 (the scene's
    colours and light directions) has three defaults, bounds that hold for each component, and
    the control that sets it: "color" (a colour picker, linear RGB) or "direction" (azimuth and
    elevation, a unit vector)."""

    name: str
    type: str  # "float", "int" or "vec3"
    default: float | int | list[float]
    min: float | int
    max: float | int
    control: str = ""  # for a vec3: "color" or "direction"

    def declaration(self) -> str:
        return f"uniform {self.type} {self.name};"
