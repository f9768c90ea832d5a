"""The rules reference page, generated from the rules' docstrings (`glint rule --all
--markdown`); site/docs/rules.md is this output, and a test keeps it current."""

from __future__ import annotations

import re

from .precision import load_measured, precision_note, table_markdown
from .rules import CATEGORY_PREFIX, all_rules, rule_doc

_FIXES = {"safe": "safe fix", "unsafe": "unsafe fix", "none": "no fix"}
_URL = re.compile(r"(?<![<(])(https?://[^\s)>]+)")


def rules_markdown() -> str:
    rules = all_rules()
    out = [
        "# Lint rules\n\n",
        "Generated from the rules' docstrings by `glint rule --all --markdown`; "
        "`glint rule CODE` prints one. Codes never change meaning. Rules marked opt-in run "
        "with `--select ALL` or when selected by code or prefix: their findings on real "
        "shaders are not yet precise enough to run by default.\n\n",
        "| code | name | severity | runs | fix | finds |\n|---|---|---|---|---|---|\n",
    ]
    for code, rule in rules.items():
        summary = rule_doc(rule)["summary"].replace("|", "\\|")
        runs = "default" if rule.default else "opt-in"
        out.append(
            f"| [{code}](#{code.lower()}) | {rule.name} | {rule.severity} | {runs} | "
            f"{_FIXES[rule.fixable]} | {summary} |\n"
        )
    out.append("\n## Precision on real shaders\n\n" + table_markdown(load_measured()) + "\n")
    for category, prefix in CATEGORY_PREFIX.items():
        members = [(c, r) for c, r in rules.items() if r.category == category]
        if not members:
            continue
        out.append(f"\n## {category.capitalize()} ({prefix})\n")
        for code, rule in members:
            doc = rule_doc(rule)
            out.append(f"\n### {code}\n\n`{rule.name}` · {rule.severity} · "
                       f"{_FIXES[rule.fixable]}\n\n{doc['summary']}\n")  # fmt: skip
            if doc["details"]:
                out.append(f"\n{_prose(doc['details'])}\n")
            out.append(f"\n**Why is this bad?** {_prose(doc['why'])}\n")
            out.append(f"\n**Example:**\n\n```glsl\n{doc['example']}\n```\n")
            if doc["fix_title"] == "Use instead":
                out.append(f"\n**Use instead:**\n\n```glsl\n{doc['fix']}\n```\n")
            else:
                out.append(f"\n**Fix:** {_prose(doc['fix'])}\n")
            out.append(f"\n**Fix safety:** {_prose(doc['fix_safety'])}\n")
            out.append(f"\n**On real shaders:** {precision_note(code)}\n")
            out.append(f"\n**References:**\n\n{_references(doc['references'])}\n")
    return "".join(out)


def _prose(text: str) -> str:
    """Paragraphs of a docstring section, each on one line."""
    return "\n\n".join(" ".join(p.split()) for p in text.split("\n\n"))


def _references(text: str) -> str:
    """The "- " items of a References section as a Markdown list, URLs as links."""
    items = [" ".join(item.split()) for item in re.split(r"(?m)^- ", text) if item.strip()]
    return "\n".join("- " + _URL.sub(r"<\1>", item) for item in items)
