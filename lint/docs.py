"""The rules reference page, generated from the rules' docstrings (`glint rule --all
--markdown`); site/docs/rules.md is this output, and a test keeps it current."""

from __future__ import annotations

from .rules import CATEGORY_PREFIX, all_rules, rule_doc

_FIXES = {"safe": "safe fix", "unsafe": "unsafe fix", "none": "no fix"}


def rules_markdown() -> str:
    rules = all_rules()
    out = [
        "# Lint rules\n\n",
        "Generated from the rules' docstrings by `glint rule --all --markdown`; "
        "`glint rule CODE` prints one. Codes never change meaning.\n\n",
        "| code | name | severity | fix | finds |\n|---|---|---|---|---|\n",
    ]
    for code, rule in rules.items():
        summary = rule_doc(rule)["summary"].replace("|", "\\|")
        out.append(
            f"| [{code}](#{code.lower()}) | {rule.name} | {rule.severity} | "
            f"{_FIXES[rule.fixable]} | {summary} |\n"
        )
    for category, prefix in CATEGORY_PREFIX.items():
        members = [(c, r) for c, r in rules.items() if r.category == category]
        if not members:
            continue
        out.append(f"\n## {category.capitalize()} ({prefix})\n")
        for code, rule in members:
            doc = rule_doc(rule)
            out.append(f"\n### {code}\n\n`{rule.name}` · {rule.severity} · "
                       f"{_FIXES[rule.fixable]}\n\n{doc['summary']}\n")  # fmt: skip
            out.append(f"\n**Why it matters.** {' '.join(doc['why'].split())}\n")
            for title, key in (("Example", "example"), ("Fix", "fix")):
                out.append(f"\n**{title}:**\n\n```glsl\n{doc[key]}\n```\n")
    return "".join(out)
