"""The user's own distance function: a GLSL file that joins the composition as a unit.

The file is parsed with glint's front end. What it defines is what the unit provides; what it
calls or names and does not define (a catalog function such as sdTorus, a constant such as PI)
is what it requires, and the resolver finds it like any other requirement. The contract:

- `float sceneDistance(vec3 p)`: required, the signed distance (or a field with a Lipschitz
  bound, [geometry] lipschitz);
- `int sceneMaterial(vec3 p)`: optional, the id of the material at p ([geometry.materials]);
- `vec3 sceneAlbedo(vec3 p, int id, vec3 albedo)`: optional, a procedural albedo made from the
  material's own (id: the material's id, 0 for [geometry] material).

Only what glint calls (the contract's functions, [geometry] setup and detail) and what they
reach joins the shader; of that, a name that is the catalog's or glint's generated scene code's
is an error naming both, every such name in one message. A helper nothing reaches is left out,
whatever its name. It may not read ShaderToy's channels: a scene binds nothing
to them, and a read would sample black. The unit keeps the file as its origin, so `glint validate`
reports a compile error at the user's file and line.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass
from pathlib import Path

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.compose.linking.reachability import prune_unreachable
from glint.compiler.compose.units import Unit
from glint.compiler.errors import InputError
from glint.compiler.glsl import FunctionDef, ModuleSymbols, analyze, reachable
from glint.compiler.scene.model import Geometry
from glint.compiler.target.shadertoy import UNIFORM_NAMES
from glint.compiler.target.sourcemap import marker_path

DISTANCE = "sceneDistance"
MATERIAL = "sceneMaterial"
ALBEDO = "sceneAlbedo"
GEOMETRY_MATERIAL = "geometryMaterial"  # glint's: the material index of the user's field


@dataclass(frozen=True)
class _Contract:
    return_type: str
    params: tuple[str, ...]
    required: bool


CONTRACT = {
    DISTANCE: _Contract("float", ("vec3",), True),
    MATERIAL: _Contract("int", ("vec3",), False),
    ALBEDO: _Contract("vec3", ("vec3", "int", "vec3"), False),
}

# ShaderToy's texture channels: a scene binds nothing to them, so a read would sample black.
CHANNELS = frozenset(f"iChannel{i}" for i in range(4))

# The functions glint's generated scene code defines (scene_code.py, field_code.py).
GENERATED_NAMES = frozenset(
    {"map", "materialAt", "surfaceAt", "shade", "shadeDirect", "mainImage", "pixelColor",
     "subsurfaceAt", "emissionAt", "submerged", "hitLift", "detailNormal", "picture0",
     "picture1", "picture2", "picture3", GEOMETRY_MATERIAL}
)  # fmt: skip


def user_unit(
    geometry: Geometry, constants: Collection[str] = (), bound: Collection[int] = ()
) -> Unit:
    """The user's file as a unit of the composition; one clear error for a file that does not
    parse, breaks the contract or takes a name that is not its to take. `constants`: the
    scene's #define names (SUN_DIR ...), which the file may use; `bound`: the channels the
    scene's materials bind to pictures, which it may read too."""
    path = geometry.path
    symbols = analyze(geometry.source, path, provided=set(UNIFORM_NAMES) - CHANNELS)
    functions = {f.name: f for f in symbols.functions}
    _check_contract(functions, path, bool(geometry.materials))
    _check_hook(functions, path, "setup", geometry.setup, "void", ())
    _check_hook(functions, path, "detail", geometry.detail, "float", ("vec3",))
    # Only what glint calls, and what that reaches, joins the shader: a helper the port left
    # behind (its old `diffuse`, its own `PI`) neither clashes nor is emitted.
    roots = {name for name in CONTRACT if name in functions}
    roots |= {hook for hook in (geometry.setup, geometry.detail) if hook is not None}
    reached = reachable(symbols, roots) & symbols.defined
    used = [f for f in symbols.functions if f.name in reached]
    pictures = {f"iChannel{c}" for c in bound}
    _check_channels(used, path, pictures)
    _check_names(reached, functions, path)
    calls = set().union(*(f.calls | f.uses for f in used)) | _global_uses(symbols, reached)
    requires = {name for name in calls if name in symbols.calls | symbols.free}
    requires -= symbols.defined | pictures
    _check_requirements(requires - set(constants), used, path)
    whole = Unit(
        id=f"user:{Path(path).name}",
        slot="scene",
        provides=tuple(sorted(reached)),
        requires=tuple(sorted(requires)),
        body=geometry.source,
        origin=marker_path(path),  # one word: a space is %20, a line break %0A
        line=1,
        summary="the scene's own distance function",
    )
    return prune_unreachable([whole], frozenset(roots))[0]


def _global_uses(symbols: ModuleSymbols, reached: set[str]) -> set[str]:
    """What the reached globals and macros name (a constant's initialiser, a macro's body)."""
    functions = {f.name for f in symbols.functions}
    return {dep for name in reached - functions for dep in symbols.deps.get(name, ())}


def _check_hook(
    functions: dict[str, FunctionDef],
    path: str,
    key: str,
    name: str | None,
    return_type: str,
    params: tuple[str, ...],
) -> None:
    """[geometry] setup and detail name a function of the file with their own prototype."""
    if name is None:
        return
    wanted = f"{return_type} {name}({', '.join(params)})"
    found = functions.get(name)
    if found is None:
        raise InputError(f"geometry.{key}: {path} defines no `{wanted}`")
    if found.return_type != return_type or tuple(p.type for p in found.params) != params:
        raise InputError(
            f"{path}:{found.line}: {found.prototype}: geometry.{key} calls it as {wanted}"
        )


def _check_contract(functions: dict[str, FunctionDef], path: str, by_id: bool) -> None:
    for name, contract in CONTRACT.items():
        found = functions.get(name)
        if found is None:
            if contract.required:
                raise InputError(
                    f"{path}: defines no `{contract.return_type} {name}(vec3 p)`, the scene's "
                    "distance function glint lights (see [geometry] in the README)"
                )
            continue
        params = tuple(p.type for p in found.params)
        if found.return_type != contract.return_type or params != contract.params:
            wanted = f"{contract.return_type} {name}({', '.join(contract.params)})"
            raise InputError(f"{path}:{found.line}: {found.prototype}: glint calls it as {wanted}")
    if by_id and MATERIAL not in functions:
        raise InputError(
            f"{path}: [geometry.materials] gives materials by id, but the file defines no "
            f"`int {MATERIAL}(vec3 p)` to return the id"
        )
    if not by_id and MATERIAL in functions:
        raise InputError(
            f"{path}:{functions[MATERIAL].line}: {MATERIAL} returns material ids, but the scene "
            "gives one [geometry] material; list them as [geometry.materials] (id = name)"
        )


def _check_channels(functions: list[FunctionDef], path: str, bound: set[str]) -> None:
    """A read of a channel no material binds (albedo_texture) is an error: ShaderToy and
    glint's renderer would sample black and light a wrong picture without a word."""
    for function in functions:
        read = sorted((CHANNELS - bound) & (function.uses | function.calls))
        if read:
            raise InputError(
                f"{path}:{function.line}: {function.name} reads {read[0]}, which no material "
                "of the scene binds to a picture, so it would sample black; bind it (a "
                f"material's albedo_texture = {read[0][-1]}) or make the pattern procedural "
                "(a noise or a hash of p)"
            )


def _check_requirements(requires: set[str], functions: list[FunctionDef], path: str) -> None:
    """Everything the file uses and does not define must come from the catalog (a library
    function, a constant) or from glint's scene code (map, for a user's own march)."""
    catalog = load_catalog()
    for name in sorted(requires):
        if catalog.providers(name) or name in GENERATED_NAMES:
            continue
        user = next((f for f in functions if name in f.calls | f.uses), None)
        where = f"{path}:{user.line}" if user else path
        what = "calls" if user is None or name in user.calls else "uses"
        raise InputError(
            f"{where}: {what} `{name}`, which neither the file nor glint's catalog defines"
        )


def _check_names(defined: set[str], functions: dict[str, FunctionDef], path: str) -> None:
    """Every name of the file that glint's code also takes, all in one error (a port from
    ShaderToy often has several: `map`, `diffuse`, `PI` ...), in the order of the file."""
    catalog = load_catalog()
    clashes: list[tuple[int, str]] = []
    for name in sorted(defined):
        line = functions[name].line if name in functions else 0
        where = f"{path}:{line}" if line else path
        if name in GENERATED_NAMES or name.startswith("object") and name[6:].isdigit():
            message = f"`{name}` is also a function of glint's generated scene code; rename yours"
            clashes.append((line, f"{where}: {message}"))
            continue
        providers = catalog.providers(name)
        if providers:
            theirs = ", ".join(f"{s.id} ({s.relpath})" for s in providers)
            message = f"`{name}` is also defined by the catalog's {theirs}; rename yours, or "
            clashes.append((line, f"{where}: {message}delete it and call the catalog's"))
    if len(clashes) == 1:
        raise InputError(clashes[0][1])
    if clashes:
        lines = "\n".join(f"  {message}" for _, message in sorted(clashes))
        raise InputError(f"{path}: {len(clashes)} names are glint's as well:\n{lines}")
