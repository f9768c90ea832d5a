"""The packages keep to their layers (compiler/layers.py) and import one another without a
cycle, between packages and between modules."""

from __future__ import annotations

import subprocess
import sys

from glint.compiler import layers
from glint.compiler.layers import Import, allowed, cycles, graph, imports, violations


def test_no_import_goes_against_the_layers() -> None:
    bad = violations(graph())
    assert not bad, "\n".join(f"{i.importer}:{i.line} imports {i.imported}" for i in bad)


def test_no_cycle_between_packages_or_modules() -> None:
    assert cycles(graph()) == []
    modules: dict[str, dict[str, list[Import]]] = {}
    for item in dict.fromkeys(imports()):
        if item.importer != item.imported:
            modules.setdefault(item.importer, {}).setdefault(item.imported, []).append(item)
    assert cycles(modules) == []


def test_the_rules_say_what_may_import_what() -> None:
    assert allowed("compose", "catalog") and not allowed("catalog", "compose")
    assert not allowed("glsl", "target")  # the front end knows no target
    assert not allowed("evaluator", "catalog")  # the evaluator needs the front end only
    assert allowed("lint", "glsl") and not allowed("lint", "compose")
    assert not allowed("compose", "lint") and allowed("cli", "lint")


def test_an_import_against_the_layers_and_a_cycle_are_found() -> None:
    up = Import("glint.compiler.glsl.parser", "glint.compiler.compose.planning.planner", 3)
    down = Import("glint.compiler.compose.planning.planner", "glint.compiler.glsl.parser", 5)
    edges = {"glsl": {"compose": [up]}, "compose": {"glsl": [down]}}
    assert violations(edges) == [up]
    assert cycles(edges) == [["compose", "glsl", "compose"]]


def test_imports_inside_functions_count() -> None:
    found = {(i.importer, i.imported) for i in imports()}
    # cli imports glslang's runner inside `glint validate`, to start fast
    assert ("glint.compiler.cli", "glint.compiler.target.glslang") in found


def test_the_command_prints_the_graph() -> None:
    out = subprocess.run(
        [sys.executable, "-m", "glint.compiler.layers"], capture_output=True, text=True
    )
    assert out.returncode == 0, out.stdout
    assert "compose -> " in out.stdout and "no cycle" in out.stdout
    assert layers.LAYERS[0] == ("errors",)
