"""P008 uniform-not-provided."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Token, Tree

from ...analysis.syntax import spec_text
from ...analysis.types import SHADERTOY_TYPES
from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register

# Statements whose first child (the do loop: second) is the condition they test.
_TESTS = {"if_statement": 0, "while_statement": 0, "do_statement": 1, "switch_statement": 0}
_ZERO = {"bool": "false", "int": "0", "uint": "0u", "float": "0.0"}


@register
class UniformNotProvided(Rule):
    """Finds `uniform` variables that ShaderToy does not provide (anything but `iTime`,
    `iResolution`, `iMouse`, `iChannel0`..`iChannel3` and its other inputs) and that the shader
    reads: ShaderToy never sets them, so they are always zero (false, 0, a zero vector).

    Such uniforms come from shaders written for another host (a GUI toggle such as `u_mode`, or
    glslsandbox's `time` and `resolution`) and pasted into ShaderToy. Uniforms never read and
    samplers (which ShaderToy's texture units alias) are not reported; the rule runs only for
    the ShaderToy target.

    Why is this bad?
        Nothing assigns the uniform, so every test of it takes the same way on every frame: a
        `uniform bool u_reflections` turns reflections off for good, a `uniform int u_mode`
        always selects mode 0, a `uniform float time` freezes the animation. What the author
        meant to switch on is dead code.

    Example:
        uniform bool u_shadows;
        ...
        if (u_shadows) col *= shadow(p, l);

    Use instead:
        const bool u_shadows = true;  // or #define, with the value meant
        ...
        if (u_shadows) col *= shadow(p, l);

    Fix safety:
        No fix: which value was meant is the author's choice.

    References:
        - ShaderToy's How To (https://www.shadertoy.com/howto): the inputs it declares
        - GLSL ES 3.00 spec §4.3.5 (Uniform): a uniform not set by the application is zero
    """

    code = "P008"
    name = "uniform-not-provided"
    certainty = "certain"
    category = "portability"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if ctx.target != "shadertoy":
            return  # another host may set it
        declared: dict[str, tuple[Token, str]] = {}
        for node in ctx.tree.children:
            if not (isinstance(node, Tree) and node.data == "variable_declaration"):
                continue
            spec = node.children[0]
            if not _is_uniform(spec):
                continue
            typ = spec_text(spec.children[-1]) if isinstance(spec, Tree) else ""
            if typ.startswith(("sampler", "isampler", "usampler")) or not typ:
                continue  # a sampler reads texture unit 0, which ShaderToy binds to iChannel0
            for decl in node.children[1:]:
                if not (isinstance(decl, Tree) and decl.data == "declarator"):
                    continue
                name, *rest = decl.children
                arrays = all(isinstance(r, Tree) and r.data == "array_specifier" for r in rest)
                if arrays and isinstance(name, Token) and str(name) not in SHADERTOY_TYPES:
                    declared[str(name)] = (name, typ + "[]" * len(rest))
        if not declared:
            return
        reads = _reads(ctx, set(declared))
        for name, (token, typ) in declared.items():
            if name not in reads:
                continue  # never read: harmless
            first_read, test = reads[name]
            zero = _ZERO.get(typ, f"{typ}(0)")
            if test is not None:
                shown = " ".join(ctx.node_text(test).split())
                shown = shown if len(shown) <= 40 else shown[:37] + "..."
                effect = f", so the test `{shown}` at line {ctx.span(test)[0]} always sees {zero}"
            else:
                effect = f" wherever it is read (first at line {ctx.span(first_read)[0]})"
            message = (
                f"uniform {typ} {name} is never set by ShaderToy: it is always {zero}{effect}; "
                "make it a const or a #define with the value meant"
            )
            yield self.report(ctx, token, message)


def _is_uniform(spec: Node) -> bool:
    if not isinstance(spec, Tree):
        return False
    return any(
        isinstance(q, Tree) and q.data == "type_qualifier" and "uniform" in map(str, q.children)
        for q in spec.children
    )


def _reads(ctx: LintContext, names: set[str]) -> dict[str, tuple[Tree, Tree | None]]:
    """For each name read in a function: its first read and the first condition (of an if,
    loop, switch or ?:) that reads it, if any."""
    parents = ctx.parents()
    found: dict[str, tuple[Tree, Tree | None]] = {}
    for node in ctx.nodes("variable"):
        name = str(node.children[0])
        if name not in names or (name in found and found[name][1] is not None):
            continue
        test = _condition_of(node, parents)
        if name not in found:
            found[name] = (node, test)
        elif test is not None:
            found[name] = (found[name][0], test)
    return found


def _condition_of(node: Tree, parents: dict[int, Tree]) -> Tree | None:
    """The condition expression the node is part of, if it is in one."""
    current: Tree = node
    while (parent := parents.get(id(current))) is not None:
        if parent.data in _TESTS:
            return current if parent.children[_TESTS[parent.data]] is current else None
        if parent.data == "ternary":
            return current if parent.children[0] is current else None
        if parent.data == "for_statement":
            return current if len(parent.children) > 2 and parent.children[1] is current else None
        if parent.data in ("compound_statement", "function_definition"):
            return None
        current = parent
    return None
