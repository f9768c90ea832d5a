"""A small scene of its own for each library snippet that a scene uses by its content rather than
by a slot (a shape's distance function, an analytic intersection, a light's term, the pattern):
the catalog card and the variant page show it at work, as they show a slot's variants.

Each scene is one object (or the object a snippet draws) on a floor, lit by a sun and the sky,
except a light's scene, lit by that light alone (and a dim sky where the light needs a
direction to come from). Whether the composed shader really holds the snippet is checked where
the picture is made (pictures.py): a scene that no longer takes it gets no picture.
"""

from __future__ import annotations

from typing import Any

from glint.compiler.catalog.loader import snippets_root

# The object each shape snippet draws, centred above the floor.
_SHAPES: dict[str, dict[str, Any]] = {
    "sphere": {"shape": "sphere", "center": [0.0, 0.0, 0.0], "radius": 0.8},
    "box": {"shape": "box", "center": [0.0, -0.2, 0.0], "size": [0.6, 0.6, 0.6]},
    "round_box": {"shape": "rounded_box", "position": [0.0, -0.2, 0.0],
                  "size": [0.6, 0.6, 0.6], "rounding": 0.2},  # fmt: skip
    "torus": {"shape": "torus", "position": [0.0, -0.4, 0.0], "radius": 0.7, "thickness": 0.25},
    "capsule": {"shape": "capsule", "position": [0.0, -0.1, 0.0], "height": 0.9, "radius": 0.35},
    "capped_cylinder": {"shape": "cylinder", "position": [0.0, -0.3, 0.0], "height": 1.2,
                        "radius": 0.5},  # fmt: skip
    "capped_cone": {"shape": "cone", "position": [0.0, -0.3, 0.0], "height": 1.2,
                    "bottom_radius": 0.6, "top_radius": 0.2},  # fmt: skip
    "ellipsoid": {"shape": "ellipsoid", "position": [0.0, -0.3, 0.0], "radii": [0.9, 0.5, 0.6]},
    "repeat": {"shape": "repeat", "spacing": [0.8, 0.0, 0.8], "count": [3, 1, 3],
               "children": [{"shape": "sphere", "center": [0.0, -0.7, 0.0], "radius": 0.3}]},
    "smooth_ops": {"shape": "union", "blend": 0.35, "children": [
        {"shape": "sphere", "center": [-0.4, -0.2, 0.0], "radius": 0.55},
        {"shape": "box", "center": [0.45, -0.35, 0.0], "size": [0.4, 0.4, 0.4]}]},
}  # fmt: skip
_TRACED = {"sphere": "sphere", "box": "box", "plane": "sphere"}  # the floor is the traced plane
_SUN = {"type": "directional", "direction": [0.5, 0.8, 0.4], "intensity": 2.5}
_SKY = {"type": "sky", "color": [0.25, 0.45, 0.8], "intensity": 0.5}
_SPOT = {"type": "spot", "position": [1.0, 1.6, 1.0], "target": [0.0, -1.0, 0.0],
         "inner": 18.0, "outer": 28.0, "intensity": 12.0}  # fmt: skip
_LIGHTS: dict[str, list[dict[str, Any]]] = {
    "directional": [_SUN],
    "response": [_SUN],  # the BRDF response every directional light goes through
    "point": [{"type": "point", "position": [1.2, 0.6, 1.2], "intensity": 6.0, "range": 8.0}],
    "sky": [{**_SKY, "intensity": 1.5}],
    "back": [
        {
            "type": "back",
            "direction": [-0.6, 0.2, -0.7],
            "color": [1.0, 0.8, 0.5],
            "intensity": 2.0,
        },
        {**_SKY, "intensity": 0.15},
    ],  # fmt: skip
    "bounce": [
        {
            "type": "bounce",
            "direction": [0.0, -1.0, 0.3],
            "color": [1.0, 0.6, 0.3],
            "intensity": 2.0,
        },
        {**_SKY, "intensity": 0.15},
    ],  # fmt: skip
    "irradiance": [{"type": "environment", "intensity": 1.0}],
    "spot": [_SPOT],
    "spot_cone": [_SPOT],  # the spot's falloff with angle: the rim of its pool of light
    "area_shadow": [
        {
            "type": "disc",
            "position": [0.6, 2.0, 0.8],
            "direction": [-0.3, -1.0, -0.4],
            "radius": 0.8,
            "intensity": 9.0,
        },
        {**_SKY, "intensity": 0.15},
    ],  # fmt: skip
}


def card_scene(snippet_id: str) -> dict[str, Any] | None:
    """The scene (as glint.compose takes a dict) that shows `snippet_id`, or None."""
    family, _, name = snippet_id.partition(".")
    objects: list[dict[str, Any]] = []
    lights = [_SUN, _SKY]
    if family == "sdf" and (name in _SHAPES or name == "plane"):
        objects = [_SHAPES[name]] if name in _SHAPES else []
    elif family == "trace" and name in _TRACED:
        objects = [_SHAPES[_TRACED[name]]]
    elif family == "light" and name in _LIGHTS:
        objects, lights = [_SHAPES["sphere"]], _LIGHTS[name]
    elif snippet_id in ("pattern.checker", "pattern.triplanar"):
        objects = [_SHAPES["sphere"]]
    else:
        return None
    clay: dict[str, Any] = {"albedo": [0.75, 0.55, 0.4], "roughness": 0.45}
    channels = {}
    if snippet_id == "pattern.triplanar":  # the example scenes' tiles, wrapped on the ball
        clay = {"albedo": [1.0, 1.0, 1.0], "roughness": 0.45, "albedo_texture": 0,
                "texture_scale": 0.8}  # fmt: skip
        channels = {"0": str(snippets_root() / "scenes" / "pictures" / "tiles.png")}
    floor = {"shape": "plane", "normal": [0.0, 1.0, 0.0], "offset": 1.0, "material": "floor"}
    return {
        "name": f"card_{family}_{name}",
        "camera": {
            "type": "lookat",
            "position": [1.7, 1.0, 2.1],
            "target": [0.0, -0.35, 0.0],
            "focal": 1.6,
        },  # fmt: skip
        "objects": [{**o, "material": "clay"} for o in objects] + [floor],
        "materials": {
            "clay": clay,
            "floor": {
                "albedo": [0.35, 0.35, 0.35],
                "pattern": "checker",
                "pattern_albedo": [0.6, 0.6, 0.6],
                "roughness": 0.8,
            },  # fmt: skip
        },
        "lights": lights,
        "environment": {"top": [0.3, 0.45, 0.7], "bottom": [0.6, 0.62, 0.65]},
        "post": {"tonemap": "aces", "output": "srgb"},
        "channels": channels,
    }
