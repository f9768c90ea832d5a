"""Parameters as uniforms (`glint compose --target webgl2 --params-as-uniforms`): the knobs a
page can turn without recompiling.

Each snippet parameter that has a numeric range (float or int) and survived pruning becomes
`uniform float NAME;` (or `uniform int`) in the parameter block instead of `#define NAME value`,
unless the shader uses it where GLSL ES 3.00 needs a constant expression: an array size, a
`const` initialiser, a global initialiser, a `case` label, or a preprocessor condition. Those are
found by parsing the shader with the uniforms in place (glint's GLSL front end), not from a list,
so a snippet that starts using a parameter as an array size keeps it a `#define` by itself.

The shader then carries a manifest for the page's sliders, a block comment of JSON right after
the parameter block:

    /* glint-params
    [{"name": "AO_STRENGTH", "type": "float", "default": 3.0, "min": 0.0, "max": 10.0}]
    */

The scene's own values join them (scene_code.py): light intensities and directions, material
albedos, roughness and metallic, exposure; a vec3 entry names its control ("color" or
"direction").
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Collection, Iterator
from dataclasses import asdict

from lark import Token, Tree

from glint.compiler.catalog.loader import Catalog
from glint.compiler.compose.codegen.knobs import UniformParam
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.units import Unit
from glint.compiler.glsl import Macro, parse_source, preprocess
from glint.compiler.glsl.ast import Variable, VariableDeclaration
from glint.compiler.glsl.pptokens import tokenize

MANIFEST_OPEN = "/* glint-params"
MANIFEST_CLOSE = "*/"
UNIFORM_TYPES = ("float", "int")  # what a slider can set
_DEFINE = re.compile(r"^#define (\w+) (.+)$")
_STORAGE = {"uniform", "in", "out"}  # globals whose initialiser need not be constant (none may)
_CONDITIONALS = ("if", "elif", "ifdef", "ifndef")


def candidates(units: list[Unit], catalog: Catalog, plan: Plan) -> dict[str, UniformParam]:
    """The parameters of `units` that a slider could set (a range, a float or int type), with
    the value the parameter block gives them (the scene's baked value, else the default)."""
    result: dict[str, UniformParam] = {}
    for name, param in catalog.params_of(u.id for u in units).items():
        if param.range is None or param.type not in UNIFORM_TYPES:
            continue
        number = int if param.type == "int" else float
        value = plan.params.get(name)
        default = number(value) if value is not None else number(param.default)
        low, high = (number(v) for v in param.range)
        result[name] = UniformParam(name, param.type, default, low, high)
    return result


def defined_params(block: str, wanted: Collection[str]) -> list[str]:
    """The names in `wanted` that the (pruned) parameter block still `#define`s, in order."""
    names = []
    for line in block.splitlines():
        match = _DEFINE.match(line)
        if match and match.group(1) in wanted:
            names.append(match.group(1))
    return names


def as_uniforms(block: str, params: Collection[UniformParam]) -> str:
    """The parameter block with each of `params` declared as a uniform instead of defined."""
    by_name = {p.name: p for p in params}
    lines = []
    for line in block.splitlines():
        match = _DEFINE.match(line)
        param = by_name.get(match.group(1)) if match else None
        lines.append(param.declaration() if param else line)
    return "\n".join(lines) + "\n"


def manifest_comment(params: Collection[UniformParam]) -> str:
    """The JSON block the page reads its sliders from (ASCII, one line, so that glslang and
    every browser take it as an ordinary comment)."""
    entries = [{k: v for k, v in asdict(p).items() if k != "control" or v} for p in params]
    data = json.dumps(entries, ensure_ascii=True)
    return f"{MANIFEST_OPEN}\n{data}\n{MANIFEST_CLOSE}\n"


def read_manifest(text: str) -> list[UniformParam]:
    """The manifest of a shader composed with uniforms; [] when it has none."""
    start = text.find(MANIFEST_OPEN + "\n")
    if start < 0:
        return []
    body = text[start + len(MANIFEST_OPEN) + 1 :]
    data = json.loads(body[: body.index(MANIFEST_CLOSE)])
    return [UniformParam(**entry) for entry in data]


def constant_uses(
    names: Collection[str], shader_with: Callable[[Collection[str]], str]
) -> set[str]:
    """The names of `names` that the shader uses where GLSL ES 3.00 needs a constant expression,
    so they must stay `#define`s. `shader_with(uniforms)` is the complete shader with those names
    as uniforms and the others defined."""
    wanted = set(names)
    plain = shader_with(())
    # The preprocessor first: it refuses a #if that reads a name no longer defined.
    found = set(_in_conditions(plain, preprocess(plain, "<params>").defines, wanted))
    tree, _ = parse_source(shader_with(sorted(wanted - found)), "<params-as-uniforms>")
    for node in _constant_expressions(tree):
        found |= {name for name in _variables(node) if name in wanted}
    return found


def _constant_expressions(tree: Tree) -> Iterator[Tree | Token]:
    """Every subtree GLSL ES 3.00 requires to be a constant expression."""
    top_level = {id(child) for child in tree.children}
    for node in tree.iter_subtrees():
        if node.data in ("array_specifier", "case_label"):
            yield node
        elif node.data == "variable_declaration":
            qualifiers = _qualifiers(node)
            # `const` anywhere; a global without a storage qualifier (ES 3.00 section 4.3)
            if "const" in qualifiers or (id(node) in top_level and not qualifiers & _STORAGE):
                for declarator in VariableDeclaration(node).declarators:
                    # the array size and the initializer
                    yield from (
                        p for p in (declarator.array, declarator.initializer) if p is not None
                    )


def _qualifiers(declaration: Tree) -> set[str]:
    return set(VariableDeclaration(declaration).type.qualifiers)


def _variables(node: Tree | Token) -> Iterator[str]:
    if isinstance(node, Tree):
        for variable in node.find_data("variable"):
            yield Variable(variable).name


def _in_conditions(source: str, macros: dict[str, Macro], wanted: set[str]) -> Iterator[str]:
    """Names of `wanted` that a `#if`, `#elif`, `#ifdef` or `#ifndef` reads, directly or through
    the macros it names (a uniform there would silently read as 0, or as undefined)."""
    pending: list[str] = []
    for line in source.splitlines():
        tokens = [t for t in tokenize(line.strip()) if t.kind != "ws"]
        if len(tokens) > 1 and tokens[0].text == "#" and tokens[1].text in _CONDITIONALS:
            pending += [t.text for t in tokens[2:] if t.kind == "ident"]
    seen: set[str] = set()
    while pending:
        name = pending.pop()
        if name in seen:
            continue
        seen.add(name)
        if name in wanted:
            yield name
        macro = macros.get(name)
        if macro is not None:
            pending += [t.text for t in tokenize(macro.body) if t.kind == "ident"]
