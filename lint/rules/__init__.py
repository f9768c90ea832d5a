"""The rule registry. A rule is a class with a stable `code`, registered by `@register`; one
package per category and one module per rule, named after its code and name
(`numerical/n001_pow_negative_base.py`), with the category's shared helpers in a module whose
name starts with `_`. `all_rules()` imports every rule module.

Codes never change meaning. Categories and their prefixes:

- C correctness (C0xx: what glslang and glint's own parser say; C1xx: data flow)
- P portability (GLSL ES 3.00 and ShaderToy)
- N numerical hazards (value-range reasoning)
- L lighting
- PF performance
- S style and the linter's own housekeeping (unused suppressions)
"""

from __future__ import annotations

import importlib
import os
import pkgutil
import re
from collections.abc import Iterator
from functools import cache
from typing import ClassVar, Literal

from ..context import LintContext
from ..finding import Certainty, Finding, Severity

Category = Literal["correctness", "portability", "numerical", "lighting", "performance", "style"]
CATEGORY_PREFIX: dict[Category, str] = {
    "correctness": "C",
    "portability": "P",
    "numerical": "N",
    "lighting": "L",
    "performance": "PF",
    "style": "S",
}
_CODE = re.compile(r"^(C|P|N|L|PF|S)\d{3}$")


class Rule:
    """Base of every rule. Subclasses set the class attributes and write `check`; the class
    docstring is the rule's documentation, in ruff's sections: a first paragraph that says what
    it finds, then "Why is this bad?", "Example:", "Use instead:" (code) or "Fix:" (prose),
    "Fix safety:" and "References:" (see SECTIONS and rule_doc)."""

    code: ClassVar[str]
    name: ClassVar[str]  # kebab-case, e.g. "pow-negative-base"
    category: ClassVar[Category]
    severity: ClassVar[Severity] = "warning"
    # How sure its findings are (finding.Certainty); a rule may say more of one finding.
    certainty: ClassVar[Certainty] = "likely"
    needs_tree: ClassVar[bool] = True  # skipped when the file did not parse
    fixable: ClassVar[Literal["safe", "unsafe", "none"]] = "none"
    runs_last: ClassVar[bool] = False  # reports on what the other rules ran into
    # In the default rule set: its findings on real shaders are worth acting on (measured by
    # lint/precision.py from labelled findings); otherwise opt-in, run by code, prefix or ALL.
    default: ClassVar[bool] = True
    # Whether a finding is glint's judgement, so the rule runs by default only when a labelled
    # sample of at least 15 of its findings on real shaders is 80 % worth acting on (a rule that
    # never fires there has no measured precision, and stays opt-in). False for the rules that
    # relay what the target's compiler rejects (glslang, the parser, GLSL ES 3.00 errors) and
    # for housekeeping of the user's own suppressions.
    judged: ClassVar[bool] = True

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        raise NotImplementedError

    def report(
        self,
        ctx: LintContext,
        where: object,
        message: str,
        fix: object = None,
        certainty: Certainty | None = None,
    ) -> Finding:
        """A finding of this rule (`where` is a tree node, a token or a span)."""
        sure = certainty or self.certainty
        return ctx.finding(self.code, self.severity, where, message, fix, sure)  # type: ignore[arg-type]


REGISTRY: dict[str, type[Rule]] = {}


def register(cls: type[Rule]) -> type[Rule]:
    """Class decorator: add a rule to the registry under its code."""
    if not _CODE.match(cls.code):
        raise ValueError(f"{cls.__name__}: code {cls.code!r} is not a category prefix + 3 digits")
    if not cls.code.startswith(CATEGORY_PREFIX[cls.category]):
        raise ValueError(f"{cls.__name__}: code {cls.code} does not match {cls.category}")
    if cls.code in REGISTRY and REGISTRY[cls.code] is not cls:
        raise ValueError(f"{cls.code} registered twice ({REGISTRY[cls.code].__name__})")
    if not (cls.__doc__ or "").strip():
        raise ValueError(f"{cls.code}: a rule needs a docstring")
    REGISTRY[cls.code] = cls
    return cls


@cache
def _import_rule_modules() -> None:
    # Once per process: the runner asks for the rules on every file, and walking the
    # packages on the file system each time cost as much as a small rule.
    for module in pkgutil.walk_packages(__path__, prefix=f"{__name__}."):
        importlib.import_module(module.name)


@cache
def rule_codes() -> frozenset[str]:
    """Every rule's code, read from the rule modules' names (`n001_pow_negative_base.py` is
    N001) without importing them: checking a code on the command line, in the configuration or
    in a cache entry need not load every rule (a test checks this equals `all_rules()`)."""
    codes = set()
    for package in pkgutil.iter_modules(__path__):
        if package.ispkg:
            folder = os.path.join(package.module_finder.path, package.name)  # type: ignore[union-attr]
            for module in pkgutil.iter_modules([folder]):
                match = _MODULE.match(module.name)
                if match:
                    codes.add(match.group(1).upper())
    return frozenset(codes)


_MODULE = re.compile(r"^((?:c|p|n|l|pf|s)\d{3})_\w+$")


def all_rules() -> dict[str, type[Rule]]:
    """Every registered rule by code, sorted; imports the rule modules on first use."""
    _import_rule_modules()
    return dict(sorted(REGISTRY.items()))


# The sections of a rule's docstring, after its first paragraph (what it finds) and any further
# paragraphs on how it decides: (head as written, key in rule_doc()). A head stands alone on its
# line, unindented, and its text is indented below it; "Use instead:" is followed by code,
# "Fix:" by prose. Every rule has all five (a test checks).
SECTIONS: tuple[tuple[str, str], ...] = (
    ("Why is this bad?", "why"),
    ("Example:", "example"),
    ("Use instead:", "fix"),
    ("Fix:", "fix"),
    ("Fix safety:", "fix_safety"),
    ("References:", "references"),
)
REQUIRED_SECTIONS = ("summary", "why", "example", "fix", "fix_safety", "references")


def rule_doc(rule: type[Rule]) -> dict[str, str]:
    """The docstring split into `summary` (its first paragraph, on one line), `details` (any
    further paragraphs before the first section), `why`, `example`, `fix`, `fix_title` ("Use
    instead" when the fix is code, "Fix" when it is prose), `fix_safety` and `references`. A
    missing section is ""."""
    text = _dedent(rule.__doc__ or "")
    sections = dict.fromkeys(("lead", "why", "example", "fix", "fix_safety", "references"), "")
    heads = {head.lower(): (head, key) for head, key in SECTIONS}
    heads["why it matters:"] = ("Why is this bad?", "why")  # the older spelling
    current, fix_title = "lead", ""
    for line in text.split("\n"):
        low = line.strip().lower()
        if line[:1].isspace():  # a section's text
            sections[current] += line + "\n"
            continue
        for prefix, (head, key) in heads.items():
            if low.startswith(prefix):  # a head, maybe with text on the same line
                current = key
                fix_title = head.rstrip(":") if key == "fix" else fix_title
                line = line.strip()[len(prefix) :]
                break
        sections[current] += line + "\n"
    doc = {k: _dedent(v).strip() for k, v in sections.items()}
    lead = doc.pop("lead").split("\n\n", 1)
    doc["summary"] = " ".join(lead[0].split())  # one line, for listings
    doc["details"] = lead[1].strip() if len(lead) > 1 else ""
    doc["why"] = doc["why"][:1].upper() + doc["why"][1:]
    doc["fix_title"] = fix_title
    order = ("summary", "details", "why", "example", "fix_title", "fix", "fix_safety", "references")
    return {key: doc[key] for key in order}


def missing_sections(rule: type[Rule]) -> list[str]:
    """The keys of REQUIRED_SECTIONS that the rule's docstring leaves empty."""
    doc = rule_doc(rule)
    return [key for key in REQUIRED_SECTIONS if not doc[key]]


def _dedent(text: str) -> str:
    import inspect

    return inspect.cleandoc(text)
