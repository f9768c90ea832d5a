"""`glint catalog show ID`: a snippet and its dependencies as one block that compiles once a
mainImage (and, where it calls the scene, a `map`) is appended; each dependency once, after what
it needs; a bad id is one clear line and exit code 1."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest

from glint.compiler.catalog.loader import glsl_value, load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.catalog_tools.show import show_source
from glint.compiler.target.glslang import validate

GLINT = [sys.executable, "-m", "glint.compiler.cli"]
CATALOG = load_catalog()
# A term, a lobe with three slot dependencies, scene-querying snippets, one that needs the sun.
SHOWN = [
    "D.ggx",
    "specular.cook_torrance",
    "normal.tetrahedron",
    "normal.derivative_flat",
    "shadow.soft",
    "attenuation.inverse_square_range",
    "background.gradient_sun",
]
TRIVIAL_MAIN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(0.0); }\n"
SCENE_MAP = "float map(vec3 p) { return length(p) - 1.0; }\n"
MARKER = re.compile(r"^// (\S+) \((snippets/\S+)\)$", re.MULTILINE)


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*GLINT, *args], capture_output=True, text=True, timeout=120)


def shown_ids(block: str) -> list[str]:
    return [match.group(1) for match in MARKER.finditer(block)]


@pytest.mark.parametrize("snippet_id", SHOWN)
def test_block_compiles_with_a_trivial_main(snippet_id: str) -> None:
    block = show_source(snippet_id)
    tail = TRIVIAL_MAIN
    if "float map(vec3 p);" in block:  # the block declares the scene's map; the user defines it
        tail = SCENE_MAP + tail
    errors = [d for d in validate(block + tail, f"{snippet_id}.glsl", "shadertoy")]
    assert [str(d) for d in errors if d.severity == "error"] == []


@pytest.mark.parametrize("snippet_id", SHOWN)
def test_each_dependency_once_and_after_what_it_needs(snippet_id: str) -> None:
    block = show_source(snippet_id)
    ids = shown_ids(block)
    assert snippet_id in ids
    assert len(ids) == len(set(ids)), f"repeated: {ids}"
    for index, unit_id in enumerate(ids):
        before = [CATALOG.snippets[i] for i in ids[:index]]
        provided = {symbol for s in before for symbol in s.provides}
        slots = {s.slot for s in before}
        for req in CATALOG.snippets[unit_id].requires:
            if req in SLOTS and not SLOTS[req].many:
                assert req in slots, f"{unit_id} needs slot {req} before it in {ids}"
            elif req not in {"map", "SUN_DIR", "SUN_COLOR"}:
                assert req in provided, f"{unit_id} needs {req} before it in {ids}"
    # The header names the same snippets, in the same order, each once.
    header = [line.split()[1] for line in block.splitlines() if line.startswith("//   ")]
    assert header == ids


def test_other_slots_take_the_balanced_tier() -> None:
    block = show_source("specular.cook_torrance")
    ids = shown_ids(block)
    assert {"D.ggx", "V.smith_ggx_correlated"} <= set(ids)
    assert not any(i.startswith("F.") for i in ids)  # the lobe is given F; it calls no fresnel


def test_parameters_are_defines_and_the_scene_is_declared_not_defined() -> None:
    block = show_source("shadow.soft")
    for name, param in CATALOG.get("shadow.soft").params.items():
        value = re.escape(glsl_value(param.default, param.type))
        assert re.search(rf"^#define {name} {value}$", block, re.MULTILINE), name
    assert "float map(vec3 p);" in block
    assert not re.search(r"float map\(vec3 p\)\s*\{", block)
    assert "mainImage" not in block
    sun = show_source("background.gradient_sun")
    assert re.search(r"^#define SUN_DIR ", sun, re.MULTILINE)


def test_show_on_the_command_line_prints_the_block() -> None:
    result = run("catalog", "show", "normal.tetrahedron")
    assert result.returncode == 0, result.stderr
    assert result.stdout == show_source("normal.tetrahedron")


@pytest.mark.parametrize(
    ("bad", "hint"), [("D.gxx", "D.ggx"), ("normal.tetrahedon", "normal.tetrahedron"),
                      ("nothing.like.it", "glint catalog")]
)  # fmt: skip
def test_unknown_id_is_one_clear_line_and_exit_1(bad: str, hint: str) -> None:
    result = run("catalog", "show", bad)
    assert result.returncode == 1
    assert "Traceback" not in result.stderr and result.stdout == ""
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("glint: ")
    assert bad in lines[0] and hint in lines[0]


def test_catalog_listing_and_json_still_work() -> None:
    listing = run("catalog")
    assert listing.returncode == 0 and "normal.tetrahedron" in listing.stdout
    entries = json.loads(run("catalog", "--json").stdout)
    assert {"attenuation.quadratic", "normal.derivative_flat"} <= {e["id"] for e in entries}
