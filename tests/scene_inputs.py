"""Scene tables for the tests of bad scene input (test_scene_values, test_scene_files,
test_scene_strings, test_scene_camera) and the one message they get."""

from __future__ import annotations

from typing import Any

import pytest

from glint.compiler.errors import InputError
from glint.compiler.scene.model import scene_from_dict


def base_scene(**more: Any) -> dict[str, Any]:
    """A red sphere under a directional light; `more` replaces or adds top-level keys."""
    data: dict[str, Any] = {
        "materials": {"m": {"albedo": [0.8, 0.2, 0.2]}},
        "objects": [{"shape": "sphere", "material": "m"}],
        "lights": [{"type": "directional", "direction": [1.0, 1.0, 1.0]}],
    }
    data.update(more)
    return data


def error(data: dict[str, Any]) -> str:
    """The message of the InputError the scene gets (as the file scene.toml)."""
    with pytest.raises(InputError) as caught:
        scene_from_dict(data, "scene.toml")
    return caught.value.message
