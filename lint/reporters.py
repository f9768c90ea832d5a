"""Output formats of `glint lint`: text with a source excerpt, concise (one line each), JSON
(the stable interface), SARIF 2.1.0 (code-scanning tools) and GitHub workflow annotations."""

from __future__ import annotations

import json
import re
from collections import Counter
from collections.abc import Callable, Sequence
from importlib.metadata import version

from glint.compiler.errors import TERMINAL_CONTROLS, printable

from .finding import Finding
from .rules import all_rules, rule_doc

FORMATS = ("text", "concise", "json", "sarif", "github")


def concise(findings: Sequence[Finding], sources: dict[str, str]) -> str:
    del sources
    return "".join(
        f"{_where(f)}: {printable(f.code)} {printable(f.message)}{_fixable(f)}\n" for f in findings
    )


def text(findings: Sequence[Finding], sources: dict[str, str]) -> str:
    """`file:line:col: CODE message`, then the line with a caret under the span."""
    out = []
    for f in findings:
        out.append(f"{_where(f)}: {printable(f.code)} {printable(f.message)}{_fixable(f)}\n")
        lines = sources.get(f.file, "").split("\n")
        if 1 <= f.line <= len(lines) and lines[f.line - 1].strip():
            source = _visible(lines[f.line - 1].removesuffix("\r").expandtabs(4))
            width = max(1, (f.end_column - f.column) if f.end_line == f.line else 1)
            width = min(width, max(1, len(source) - f.column + 1))
            gutter = f"{f.line:>5} | "
            out.append(f"{gutter}{source}\n{' ' * (len(gutter) + f.column - 1)}{'^' * width}\n")
    return "".join(out)


def as_json(findings: Sequence[Finding], sources: dict[str, str]) -> str:
    del sources
    return json.dumps([f.as_json() for f in findings], indent=2) + "\n"


def github(findings: Sequence[Finding], sources: dict[str, str]) -> str:
    """Workflow commands (`::error file=...::message`), escaped as GitHub's runner reads them:
    in a property `%`, CR, LF, `:` and `,`; in the message `%`, CR and LF. Unescaped, a file
    name holding a line break would start a workflow command of its own."""
    del sources
    level = {"error": "error", "warning": "warning", "info": "notice"}
    return "".join(
        f"::{level[f.severity]} file={_property(f.file)},line={f.line},col={f.column},"
        f"endLine={f.end_line},endColumn={f.end_column},title={_property(f.code)}::"
        f"{_data(f.message)}\n"
        for f in findings
    )


def sarif(findings: Sequence[Finding], sources: dict[str, str]) -> str:
    del sources
    rules = all_rules()
    used = sorted({f.code for f in findings})
    level = {"error": "error", "warning": "warning", "info": "note"}
    driver = {
        "name": "glint",
        "version": version("glint"),
        "rules": [
            {
                "id": code,
                "name": rules[code].name,
                "shortDescription": {"text": rule_doc(rules[code])["summary"]},
                "help": {"text": rule_doc(rules[code])["why"]},
                "defaultConfiguration": {"level": level[rules[code].severity]},
            }
            for code in used
            if code in rules
        ],
    }
    results = [
        {
            "ruleId": f.code,
            "level": level[f.severity],
            "message": {"text": f.message},
            "properties": {"certainty": f.certainty},
            "locations": [_location(f)],
        }
        for f in findings
    ]
    log = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{"tool": {"driver": driver}, "results": results}],
    }
    return json.dumps(log, indent=2) + "\n"


REPORTERS: dict[str, Callable[[Sequence[Finding], dict[str, str]], str]] = {
    "text": text,
    "concise": concise,
    "json": as_json,
    "sarif": sarif,
    "github": github,
}


def statistics(findings: Sequence[Finding]) -> str:
    """Count per code, most frequent first, with the rule's name and whether it is fixable."""
    rules = all_rules()
    counts = Counter(f.code for f in findings)
    fixable = Counter(f.code for f in findings if f.fix is not None)
    lines = []
    for code, count in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        name = rules[code].name if code in rules else ""
        mark = " [*]" if fixable[code] else ""
        lines.append(f"{count:>6}  {code:<6} {name}{mark}\n")
    return "".join(lines)


def summary(findings: Sequence[Finding], fixed: int) -> str:
    n = len(findings)
    parts = [f"Found {n} finding{'s' if n != 1 else ''}" if n else "All clean"]
    if fixed:
        parts.append(f"fixed {fixed}")
    safe = sum(1 for f in findings if f.fix is not None and f.fix.applicability == "safe")
    unsafe = sum(1 for f in findings if f.fix is not None and f.fix.applicability == "unsafe")
    if safe:
        parts.append(f"{safe} fixable with --fix")
    if unsafe:
        parts.append(f"{unsafe} more with --unsafe-fixes")
    return "; ".join(parts) + ".\n"


def _where(f: Finding) -> str:
    return f"{printable(f.file)}:{f.line}:{f.column}"


def _fixable(f: Finding) -> str:
    return " [*]" if f.fix is not None and f.fix.applicability == "safe" else ""


def _data(message: str) -> str:
    """A workflow command's message, escaped (actions/toolkit `escapeData`)."""
    return message.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _property(value: str) -> str:
    """A workflow command's property value, escaped (actions/toolkit `escapeProperty`)."""
    return _data(value).replace(":", "%3A").replace(",", "%2C")


def _visible(line: str) -> str:
    """A source line for the excerpt: each control character as its Unicode control picture
    (ESC as U+241B), one column wide like the character it shows, so the caret stays put."""
    return TERMINAL_CONTROLS.sub(_picture, line)


def _picture(match: re.Match[str]) -> str:
    code = ord(match.group())
    return chr(0x2400 + code) if code < 0x20 else "\u2421" if code == 0x7F else "\ufffd"


# A pass of a ShaderToy project's JSON, as lint names it: PROJECT.json:PASS.
_PROJECT_PASS = re.compile(r"^(?P<file>.+\.json):(?P<pass>Common|Image|Buffer [A-D])$")


def _location(f: Finding) -> dict[str, object]:
    """A finding's SARIF location: the file and the region; for a pass of a project's JSON, the
    JSON file and the pass as a logical location (the lines count from the pass's code)."""
    project = _PROJECT_PASS.match(f.file)
    region = {"startLine": f.line, "startColumn": f.column, "endLine": f.end_line,
              "endColumn": f.end_column}  # fmt: skip
    if project is None:
        return {"physicalLocation": {"artifactLocation": {"uri": f.file}, "region": region}}
    return {
        "physicalLocation": {"artifactLocation": {"uri": project["file"]}, "region": region},
        "logicalLocations": [
            {"name": project["pass"], "fullyQualifiedName": f.file, "kind": "module"}
        ],
    }
