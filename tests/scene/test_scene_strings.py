"""Strings of a scene (its name, a material's, a file's) reach the shader only inside
comments, escaped: no line break, control character or `*/` of theirs can end a comment and
write code; a mesh scene's material names, which name files, are refused unless safe."""

from __future__ import annotations

from pathlib import Path

from scene_inputs import base_scene, error

import glint
from glint.compiler.scene.values import comment_text
from glint.compiler.target.glslang import validate

HOSTILE = "x */ vec3 injected; /* \n#error injected\r\n\\\u2028\u202e\x00 y\\"


def test_comment_text_leaves_one_line_with_no_comment_end() -> None:
    text = comment_text(HOSTILE)
    assert "\n" not in text and "\r" not in text and "*/" not in text and "/*" not in text
    assert not any(ord(c) < 32 or c in "\u2028\u202e" for c in text)
    assert comment_text("metal_spheres") == "metal_spheres"


def test_a_hostile_scene_name_stays_in_the_header_comment() -> None:
    shader = glint.compose(base_scene(name=HOSTILE))
    assert "#error" not in [line.strip()[:6] for line in shader.text.splitlines()]
    assert "vec3 injected" in shader.text.splitlines()[0]  # escaped, on the first line
    assert validate(shader.text, "<hostile>", "shadertoy") == []


def test_a_hostile_geometry_file_name_stays_in_comments(tmp_path: Path) -> None:
    name = "my map\n#error injected.glsl"  # a file name holds no '/', so no '*/'
    (tmp_path / name).write_text("float sceneDistance(vec3 p) { return length(p) - 1.0; }\n")
    scene = tmp_path / "scene.toml"
    scene.write_text(
        'name = "a\\nb"\n[geometry]\nfile = "my map\\n#error injected.glsl"\n'
        'material = "m"\n[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n'
    )
    shader = glint.compose(scene)
    lines = shader.text.splitlines()
    assert not any(line.startswith("#error") for line in lines)
    assert any(line.startswith("// source: ") and "my%20map%0A#error" in line for line in lines)
    assert validate(shader.text, "<hostile>", "shadertoy") == []


def test_mesh_material_names_become_file_names_only_when_safe() -> None:
    data = {
        "objects": [{"shape": "mesh", "builtin": "cube", "material": "../up"},
                    {"shape": "mesh", "builtin": "cube", "material": "m"}],
        "materials": {"../up": {"albedo": [1.0, 1.0, 1.0]}, "m": {"albedo": [1.0, 1.0, 1.0]}},
    }  # fmt: skip
    message = error(data)
    assert "materials: the name '../up' names a program of a mesh scene" in message
