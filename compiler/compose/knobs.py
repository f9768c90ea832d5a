"""A value a page can set live through a uniform: the entry of a shader's parameter manifest
(uniform_params.py) for a snippet parameter or one of the scene's own values (scene_code.py).
Its own module, with no imports of the composer's, so that both can name it."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class UniformParam:
    """One manifest entry: a parameter the page sets through a uniform."""

    name: str
    type: str  # "float" or "int"
    default: float | int
    min: float | int
    max: float | int

    def declaration(self) -> str:
        return f"uniform {self.type} {self.name};"
