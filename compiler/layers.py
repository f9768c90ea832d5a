"""The layers of glint and the imports between them.

    python -m glint.compiler.layers

prints each package's imports of other packages, then every import that goes against the layers
and every cycle between packages; it exits 1 when there is one. tests/test_layers.py runs the
same check.

A package may import its own modules and packages of lower layers, never one of its own layer
or above. The order is the pipeline's: the GLSL front end knows nothing of targets, the target
nothing of the catalog, the catalog nothing of composing, and so on up to the commands. The
linter stands beside the compiler and uses only the front end, the target, the errors, files and
the collector pause.
Imports inside functions count: they hide a dependency, they do not remove it.
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

_ROOT = Path(__file__).resolve().parents[1]

# Lowest first. Each entry is a layer: the packages in it (a package is a folder under
# compiler/, `lint` for the linter, `api` for `import glint`; a module at the top of compiler/
# is its own package).
LAYERS: list[tuple[str, ...]] = [
    ("errors",),
    # reading input files, writing output files whole; page text escaped; Python's cycle
    # collector paused around big builds (a parse, one file's lint)
    ("files", "markdown", "collector"),
    ("glsl",),
    ("target", "evaluator"),  # the evaluator runs GLSL on the CPU: it needs the front end only
    ("scene",),  # the scene model: what a scene file says, validated; no snippet, no code
    ("catalog",),
    ("compose",),  # bakes parameters with the evaluator (spherical harmonics of the sky)
    ("catalog_tools",),  # `glint catalog show` and its HLSL/MSL: a snippet composed to be shown
    ("render",),
    ("verify",),
    ("bench",),
    ("api",),  # `import glint`: what the commands do, as functions
    ("cli", "layers"),  # the `glint` command, a thin layer over the API
    ("site",),  # the docs site's generated pages: documents everything below it
]
# The linter sits beside the compiler's stages: what it may use of them.
LINT_USES = {"errors", "collector", "files", "glsl", "target"}

_SOURCES = {"compiler": "glint.compiler", "lint": "glint.lint"}


@dataclass(frozen=True)
class Import:
    importer: str  # dotted module name
    imported: str  # dotted module name (or package)
    line: int

    def packages(self) -> tuple[str, str]:
        return package_of(self.importer), package_of(self.imported)


def package_of(module: str) -> str:
    """`glint.compiler.compose.planning.planner` -> `compose`; `glint.lint.rules.x` -> `lint`;
    `glint` (the public API, in compiler/api) -> `api`."""
    parts = module.split(".")
    if parts[:2] == ["glint", "lint"]:
        return "lint"
    if parts[:2] == ["glint", "compiler"] and len(parts) > 2:
        return parts[2]
    return "api"


def _module_name(path: Path) -> str:
    rel = path.relative_to(_ROOT).with_suffix("")
    top, *rest = rel.parts
    if top == "compiler" and rest[:1] == ["api"]:
        dotted = ["glint", *rest[1:]]
    else:
        dotted = [*_SOURCES[top].split("."), *rest]
    if dotted[-1] == "__init__":
        dotted.pop()
    return ".".join(dotted)


def imports() -> Iterator[Import]:
    """Every import of a glint module by a glint module (relative ones resolved)."""
    for top in _SOURCES:
        for path in sorted((_ROOT / top).rglob("*.py")):
            module = _module_name(path)
            package = module if path.name == "__init__.py" else module.rpartition(".")[0]
            tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
            for node in ast.walk(tree):
                if isinstance(node, ast.Import):
                    names = [alias.name for alias in node.names]
                elif isinstance(node, ast.ImportFrom):
                    base = node.module or ""
                    if node.level:
                        anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                        base = ".".join([*anchor, *([base] if base else [])])
                    # `from pkg import module` imports the module
                    names = [f"{base}.{alias.name}" for alias in node.names] or [base]
                    names = [n if _is_module(n) else base for n in names]
                else:
                    continue
                for name in names:
                    if name == "glint" or name.startswith("glint."):
                        yield Import(module, name, node.lineno)


def _is_module(dotted: str) -> bool:
    parts = dotted.split(".")
    if parts[:2] == ["glint", "compiler"]:
        base = _ROOT / "compiler" / Path(*parts[2:]) if len(parts) > 2 else _ROOT / "compiler"
    elif parts[:2] == ["glint", "lint"]:
        base = _ROOT / "lint" / Path(*parts[2:]) if len(parts) > 2 else _ROOT / "lint"
    else:
        base = _ROOT / "compiler" / "api" / Path(*parts[1:])
    return base.with_suffix(".py").is_file() or (base / "__init__.py").is_file()


def _rank(package: str) -> int | None:
    for index, layer in enumerate(LAYERS):
        if package in layer:
            return index
    return None


def allowed(importer: str, imported: str) -> bool:
    """Whether package `importer` may import package `imported`."""
    if importer == imported:
        return True
    if importer == "lint":
        return imported in LINT_USES
    if imported == "lint":
        # the commands and the API offer the linter; the docs site documents its rules
        return importer in ("cli", "api", "site")
    low, high = _rank(imported), _rank(importer)
    return low is not None and high is not None and low < high


def graph() -> dict[str, dict[str, list[Import]]]:
    """package -> imported package -> the imports behind that edge."""
    edges: dict[str, dict[str, list[Import]]] = {}
    for item in dict.fromkeys(imports()):  # `from m import a, b` is one import of m
        src, dst = item.packages()
        if src != dst:
            edges.setdefault(src, {}).setdefault(dst, []).append(item)
    return edges


def violations(edges: dict[str, dict[str, list[Import]]]) -> list[Import]:
    return [
        item
        for src, targets in edges.items()
        for dst, items in targets.items()
        if not allowed(src, dst)
        for item in items
    ]


def cycles(edges: dict[str, dict[str, list[Import]]]) -> list[list[str]]:
    """Each cycle between packages once, as the packages along it."""
    found: list[list[str]] = []
    seen: set[frozenset[str]] = set()

    def visit(node: str, path: list[str]) -> None:
        for nxt in sorted(edges.get(node, {})):
            if nxt in path:
                cycle = path[path.index(nxt) :]
                if frozenset(cycle) not in seen:
                    seen.add(frozenset(cycle))
                    found.append([*cycle, nxt])
            elif len(path) < len(edges) + 1:
                visit(nxt, [*path, nxt])

    for start in sorted(edges):
        visit(start, [start])
    return found


def report() -> tuple[str, bool]:
    """The printed graph, and whether the layers hold."""
    edges = graph()
    lines = ["Layers, lowest first (a package may import only from layers below it):"]
    lines += [f"  {index}. {', '.join(layer)}" for index, layer in enumerate(LAYERS)]
    lines.append(f"  beside them: lint (uses {', '.join(sorted(LINT_USES))})")
    lines.append("")
    lines.append("Imports between packages:")
    for src in sorted(edges):
        lines.append(f"  {src} -> {', '.join(sorted(edges[src]))}")
    bad = violations(edges)
    loops = cycles(edges)
    lines.append("")
    if bad:
        lines.append("Imports against the layers:")
        for item in bad:
            src, dst = item.packages()
            lines.append(f"  {item.importer}:{item.line} imports {item.imported} ({src} -> {dst})")
    if loops:
        lines.append("Cycles between packages:")
        lines += ["  " + " -> ".join(cycle) for cycle in loops]
    if not bad and not loops:
        lines.append("No import goes against the layers, and there is no cycle.")
    return "\n".join(lines), not bad and not loops


def main() -> int:
    text, ok = report()
    print(text)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
