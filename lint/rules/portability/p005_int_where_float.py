"""P005 int-where-float."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import (
    Arguments,
    Assignment,
    Binary,
    Call,
    Constructor,
    Declarator,
    FunctionDefinition,
    FunctionPrototype,
    Ternary,
    Unary,
    VariableDeclaration,
    token_text,
)
from glint.compiler.glsl.keywords import words
from glint.compiler.glsl.types import is_float_like

from ...analysis.expression_types import ExpressionTypes, expression_types
from ...analysis.syntax import prototype_parts, type_of_declaration
from ...context import LintContext, walk_kind
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import function_prototypes

# Builtins with only float overloads: an int argument never matches (GLSL ES 3.00, section 8).
FLOAT_ONLY = words(
    """radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow exp log
    exp2 log2 sqrt inversesqrt floor trunc round roundEven ceil fract mod mix step smoothstep
    length distance dot cross normalize faceforward reflect refract dFdx dFdy fwidth"""
)


# Builtins with int overloads too: an int literal is wrong only beside a float argument.
INT_OVERLOADS = frozenset({"abs", "sign", "min", "max", "clamp"})


# Texture functions whose argument at this position is a float (bias or level of detail).
FLOAT_ARG_AT = {"texture": 2, "textureProj": 2, "textureLod": 2, "textureProjLod": 2}


_ARITHMETIC = frozenset({"+", "-", "*", "/", "<", ">", "<=", ">=", "==", "!="})


_DECIMAL = re.compile(r"^(0|[1-9][0-9]*)$")


@register
class IntWhereFloat(Rule):
    """Finds an int where a float is needed: `float x = 1;`, `x * 2` or `x > 0` with a float `x`,
    `pow(x, 2)`, `textureLod(s, uv, 0)`, `return 0;` in a float function. Constructors convert, so
    `vec3(1, 0, 0)` is fine.

    Why is this bad?
        GLSL ES has no implicit int-to-float conversion (desktop GL does), so code that compiles on
        a desktop driver fails on ShaderToy, WebGL and phones.

    Example:
        float d = 1;
        col *= pow(d, 2);

    Use instead:
        float d = 1.0;
        col *= pow(d, 2.0);

    Fix safety:
        Safe: an int literal becomes the float literal of the same value, which is what desktop GL's
        implicit conversion computes. An int variable needs `float(i)`, written by hand.

    References:
        - GLSL ES 3.00 spec §4.1 (Basic Types: no implicit conversions) and §5.4.1 (Conversion and
          Scalar Constructors)
    """

    code = "P005"
    name = "int-where-float"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        typed = expression_types(ctx)
        types = typed.type_of
        parents = ctx.parents()
        for node in walk_kind(ctx.tree, "int_literal", "variable"):
            if node.data == "int_literal":
                if str(token_text(node))[-1] in "uU":
                    continue
                expr: Tree = node
                while (parent := Unary.cast(parents.get(id(expr)))) is not None \
                        and parent.op in ("-", "+"):  # fmt: skip
                    expr = parent.syntax
            elif node.data == "variable" and types(node) == "int":
                expr = node
            else:
                continue
            why = self.float_context(expr, parents, typed)
            if why is None:
                continue
            text = str(token_text(node))
            if node.data == "variable":
                message = (f"int `{text}` {why}; GLSL ES has no implicit conversion: "
                           f"write `float({text})`")  # fmt: skip
                yield self.report(ctx, node, message)
                continue
            fix = None
            if _DECIMAL.match(text):
                edit = ctx.replace(node, text + ".0")
                fix = Fix(f"write `{text}.0`", (edit,)) if edit else None
            message = (f"int literal `{text}` {why}; GLSL ES has no implicit conversion: "
                       f"write `{text}.0`")  # fmt: skip
            yield self.report(ctx, node, message, fix)

    def float_context(
        self, expr: Tree, parents: dict[int, Tree], typed: ExpressionTypes
    ) -> str | None:
        """Why the expression must be a float there, or None if it need not (or we cannot
        tell)."""
        types = typed.type_of
        while True:
            parent = parents.get(id(expr))
            if parent is None:
                return None
            kind = parent.data
            if kind == "declarator" and expr is (declarator := Declarator(parent)).initializer:
                decl = VariableDeclaration.cast(parents.get(id(parent)))
                if decl is None:
                    return None
                ty, arr = type_of_declaration(decl.type.syntax)
                is_arr = arr or declarator.array is not None
                return "initialises a float" if ty == "float" and not is_arr else None
            if kind == "assignment" and expr is (assignment := Assignment(parent)).value:
                target = types(assignment.target)
                if assignment.op == "=":
                    return "is assigned to a float" if target == "float" else None
                op = assignment.op
                return f"is used in `{op}` on a float" if is_float_like(target) else None
            if kind == "binary" and (binary := Binary(parent)).op in _ARITHMETIC:
                other = binary.right if expr is binary.left else binary.left
                if is_float_like(types(other)):
                    return f"is an operand of `{binary.op}` beside a float"
                return None
            if kind == "arguments":
                return self.argument(expr, parent, parents, typed)
            if kind == "jump_statement":
                function = parents.get(id(parent))
                while function is not None and function.data != "function_definition":
                    function = parents.get(id(function))
                if function is None:
                    return None
                ret, name, _ = prototype_parts(FunctionDefinition(function).prototype.syntax)
                return f"is returned from `{name}`, which returns float" if ret == "float" else None
            if kind == "ternary" and expr is not (ternary := Ternary(parent)).condition:
                other = ternary.if_false if expr is ternary.if_true else ternary.if_true
                if is_float_like(types(other)):
                    return "is a branch of `?:` beside a float"
                expr = parent  # the ternary's own context decides
                continue
            return None

    def argument(
        self, expr: Tree, args: Tree, parents: dict[int, Tree], typed: ExpressionTypes
    ) -> str | None:
        call = parents.get(id(args))
        items = Arguments(args).items
        position = next(i for i, a in enumerate(items) if a is expr)
        if call is None:
            return None
        if call.data == "constructor":
            ty, arr = type_of_declaration(Constructor(call).type.syntax)
            if arr:
                return "is an element of a float array" if ty == "float" else None
            # struct constructors convert nothing; vector and matrix constructors do
            members = list(typed.structs.get(ty, {}).items())
            if len(members) == len(items) and members[position][1] == "float":
                return f"initialises the float member `{members[position][0]}` of `{ty}`"
            return None
        name = Call(call).callee_name if call.data == "call" else None
        if name is None:
            return None
        count = len(items)
        own = {FunctionPrototype(p).name for p in function_prototypes(typed.tree)}
        if name in own:  # the file's own function, every overload taking a float
            overloads = [p for p in typed.parameters.get(name, []) if len(p) == count]
            if overloads and all(p[position][1] == "float" for p in overloads):
                return f"is passed to a float parameter of `{name}`"
            return None
        if name in FLOAT_ONLY:
            return f"is passed to `{name}`, which takes floats"
        if FLOAT_ARG_AT.get(name) == position:
            return f"is passed as `{name}`'s float bias or level"
        others = [a for i, a in enumerate(items) if i != position]
        if name in INT_OVERLOADS and any(is_float_like(typed.type_of(a)) for a in others):
            return f"is passed to `{name}` beside a float argument"
        return None
