"""C109 inconsistent-twin-line."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Field, variable_name

from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register
from ._twins import shape, subtrees, twin_kind

_STATEMENTS = ("expression_statement", "declaration_statement")


@register
class InconsistentTwinLine(Rule):
    """Finds two adjacent statements of the same shape, written by copying one and renaming a
    vector to its twin (`p1` to `p2`), where the copy reads one component of the renamed vector
    in two places that the original reads as two different components: the copy collapsed
    `p1.y ... p1.x` into `p2.x ... p2.x`, so `p2.y` is never used.

    Only components of variables renamed to a twin name (one digit or axis letter apart) count,
    and both statements must be the same expression but for names, numbers and operators.

    Why is this bad?
        The copy was meant to read the same components of its own vector: one of them was left
        at the wrong letter, so a parameter (a frequency, an offset) is used in two roles and
        the other is ignored. Each line is valid, so no compiler warns.

    Example:
        float b1 = P1.x * texture(iChannel0, uv * P1.y).x;
        float b2 = P2.x * texture(iChannel0, uv * P2.x).x;

    Use instead:
        float b1 = P1.x * texture(iChannel0, uv * P1.y).x;
        float b2 = P2.x * texture(iChannel0, uv * P2.y).x;

    Fix safety:
        No fix: the letter is very likely the original's, but the author must confirm.

    References:
        - Beller et al., "Analyzing the last line effect" (copy-paste slips in parallel code)
    """

    code = "C109"
    name = "inconsistent-twin-line"
    default = False  # opt-in: fewer than 15 findings on the corpus to judge it by
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for block in ctx.nodes("compound_statement"):
            statements = [c for c in block.children if isinstance(c, Tree)]
            shapes: dict[int, list[tuple[str, str]]] = {}
            for first, second in zip(statements, statements[1:], strict=False):
                if first.data not in _STATEMENTS or second.data != first.data:
                    continue
                a = shapes.get(id(first)) or shape(first)
                b = shapes[id(second)] = shape(second)
                if not _same_form(a, b):
                    continue
                found = _collapse(subtrees(first), subtrees(second))
                if found is not None:
                    yield self._finding(ctx, *found)

    def _finding(self, ctx: LintContext, bad: Tree, good: Tree, other: Tree) -> Finding:
        wrong, right = Field(bad), Field(good)
        base, letter = ctx.node_text(wrong.base).strip(), wrong.name
        meant = right.name
        twin = ctx.node_text(right.base).strip()
        message = (
            f"`{base}.{letter}` here is `{twin}.{meant}` in the twin statement at line "
            f"{ctx.span(good)[0]}, which reads {twin}.{meant} and "
            f"{twin}.{Field(other).name} where this one reads {base}.{letter} twice: "
            f"`{base}.{meant}` was probably meant (this statement never reads {base}.{meant})"
        )
        return self.report(ctx, bad, message)


def _same_form(a: list[tuple[str, str]], b: list[tuple[str, str]]) -> bool:
    """The same tree and token kinds at every position (names and numbers may differ)."""
    if len(a) != len(b) or a == b:
        return False
    return all(x[0] == y[0] and (x[0] != "T" or x[1] == y[1]) for x, y in zip(a, b, strict=True))


def _collapse(first: list[Node], second: list[Node]) -> tuple[Tree, Tree, Tree] | None:
    """(the component read in the wrong place, the same place in the twin statement, the
    twin's other component that this one duplicates), or None. Fields are paired by position
    among those of a variable renamed to its twin."""
    pairs: dict[tuple[str, str], list[tuple[Tree, Tree]]] = {}
    for x, y in zip(first, second, strict=True):
        bx, by = _field_base(x), _field_base(y)
        if bx is not None and by is not None and twin_kind(bx, by) is not None:
            pairs.setdefault((bx, by), []).append((x, y))  # type: ignore[arg-type]
    for fields in pairs.values():
        for i, (xi, yi) in enumerate(fields):
            for xj, yj in fields[i + 1 :]:
                a_i, a_j, b_i, b_j = (Field(n).name for n in (xi, xj, yi, yj))
                if a_i != a_j and b_i == b_j:  # the second statement collapsed two letters
                    return (yi, xi, xj) if b_i != a_i else (yj, xj, xi)
                if b_i != b_j and a_i == a_j:  # the first did
                    return (xi, yi, yj) if a_i != b_i else (xj, yj, yi)
    return None


def _field_base(node: Node) -> str | None:
    """`v` for a swizzle or field `v.x` of a plain variable."""
    field = Field.cast(node)
    return variable_name(field.base) if field is not None else None
