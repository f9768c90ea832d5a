"""S001 unused-suppression."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from ...suppressions import Suppression
from .. import Rule, all_rules, register

UNUSED_SUPPRESSION = "S001"


@register
class UnusedSuppression(Rule):
    """Finds a `// glint: ignore[...]` or `file-ignore[...]` comment that silences nothing, or that
    names a code no rule has.

    Why is this bad?
        A suppression outlives the problem it hid; stale ones hide the next real finding on that
        line, and a misspelt code silences nothing while looking as if it did.

    Example:
        float d = max(dot(N, L), 0.0); // glint: ignore[N001]

    Fix:
        Remove the comment, or correct the code it names (`glint rule --all` lists them).

    Fix safety:
        No fix.

    References:
        - glint's README, Lint section (suppressions)
        - ruff's RUF100 (unused-noqa), the model for this rule
    """

    code = UNUSED_SUPPRESSION
    certainty = "certain"
    name = "unused-suppression"
    judged = False  # housekeeping of the user's own suppressions
    category = "style"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        return iter(())  # reported by the runner through `unused_suppressions`


def unused_suppressions(
    ctx: LintContext, suppressions: list[Suppression], ran: set[str]
) -> list[Finding]:
    """S001 findings: suppressions that silenced nothing of what ran, or name unknown codes."""
    known = set(all_rules())
    found = []
    for s in suppressions:
        span = (s.line, s.column, s.line, s.end_column)
        if s.codes is None:
            if not s.used:
                found.append(
                    ctx.finding(
                        UNUSED_SUPPRESSION,
                        "warning",
                        span,
                        "suppression silences nothing; remove it",
                        certainty="certain",
                    )
                )
            continue
        unknown = sorted(s.codes - known)
        unused = sorted(c for c in s.codes & ran if c not in s.used)
        if unknown:
            message = f"suppression names unknown code{'s' if len(unknown) > 1 else ''} " + (
                ", ".join(unknown) + "; see `glint rule --all`"
            )
            found.append(ctx.finding(UNUSED_SUPPRESSION, "warning", span, message, None, "certain"))
        if unused:
            message = f"unused suppression of {', '.join(unused)}: nothing to silence; remove it"
            found.append(ctx.finding(UNUSED_SUPPRESSION, "warning", span, message, None, "certain"))
    return found
