"""The lint documentation tells the truth: the rules page is generated from the docstrings as
they are now, and the lint run shown in the README is what glint prints."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from glint.lint.docs import rules_markdown
from glint.lint.rules import all_rules

ROOT = Path(__file__).resolve().parents[2]


def test_rules_page_is_current() -> None:
    page = (ROOT / "site" / "docs" / "rules.md").read_text(encoding="utf-8")
    assert page == rules_markdown(), "regenerate: glint rule --all --markdown > site/docs/rules.md"


def test_rules_page_has_a_section_per_rule() -> None:
    page = rules_markdown()
    assert all(f"\n### {code}\n" in page for code in all_rules())


def test_readme_lint_run_is_what_glint_prints() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    match = re.search(r"```\n\$ glint lint ([^\n]+)\n(.*?)```", readme, re.S)
    assert match, "the README shows a lint run"
    result = subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", "lint", *match.group(1).split()],
        capture_output=True, text=True, cwd=ROOT, timeout=120,
    )  # fmt: skip
    assert result.returncode == 1
    assert result.stdout == match.group(2)
