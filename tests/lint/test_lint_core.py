"""The linter's core: selection by code and prefix, inline suppressions and the unused-
suppression finding, configuration from pyproject.toml, fixes, and every output format."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from glint.compiler.errors import UsageError
from glint.lint.config import load_options, options_from_table
from glint.lint.finding import Edit, Finding, Fix
from glint.lint.fixes import apply_edits
from glint.lint.options import Options
from glint.lint.reporters import REPORTERS, statistics
from glint.lint.rules import REGISTRY, all_rules, missing_sections, rule_doc
from glint.lint.runner import lint_bytes, lint_source

BROKEN = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0)\n}\n"  # a syntax error


def codes(findings: list[Finding]) -> list[str]:
    return [f.code for f in findings]


# --- registry ---------------------------------------------------------------------------------


def test_every_rule_has_a_stable_code_a_name_and_every_doc_section() -> None:
    for code, rule in all_rules().items():
        assert rule.code == code and rule.name and rule.name == rule.name.lower()
        assert not missing_sections(rule), f"{code} lacks {missing_sections(rule)}"
        assert rule.fixable in ("safe", "unsafe", "none")


def test_a_rule_without_a_section_is_caught() -> None:
    from glint.lint.rules import Rule

    class NoReferences(Rule):
        """Finds nothing.

        Why is this bad?
            It is not.

        Example:
            vec4(1.0);

        Use instead:
            vec4(1.0);

        Fix safety:
            No fix.
        """

    doc = rule_doc(NoReferences)
    assert doc["summary"] == "Finds nothing." and doc["fix_title"] == "Use instead"
    assert doc["example"] == doc["fix"] == "vec4(1.0);" and doc["fix_safety"] == "No fix."
    assert missing_sections(NoReferences) == ["references"]


def test_fix_safety_says_what_the_rule_offers() -> None:
    opening = {"safe": "Safe", "unsafe": "Unsafe", "none": "No fix"}
    for code, rule in all_rules().items():
        doc = rule_doc(rule)
        assert doc["fix_safety"].startswith(opening[rule.fixable]), code
        # a fix shown as code is a code block; a fix described in words is prose
        assert doc["fix_title"] in ("Use instead", "Fix"), code


def test_the_registry_rejects_a_code_outside_its_category() -> None:
    from glint.lint.rules import Rule, register

    class Wrong(Rule):
        """Finds nothing.

        Why it matters: no.
        Example: none.
        Fix: none.
        """

        code = "N999"
        name = "wrong"
        category = "lighting"

    with pytest.raises(ValueError, match="does not match lighting"):
        register(Wrong)
    assert "N999" not in REGISTRY


# --- options ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("select", "ignore", "code", "enabled"),
    [
        (["ALL"], [], "N001", True),
        (["N"], [], "N001", True),
        (["N"], [], "L001", False),
        (["N"], ["N005"], "N005", False),
        (["N005"], ["N"], "N005", True),  # the more specific pattern wins
        (["P"], [], "PF001", False),  # a letter prefix is one category, not a string prefix
        (["PF"], [], "PF001", True),
        (["ALL"], ["C"], "C001", False),
    ],
)
def test_select_and_ignore(select: list[str], ignore: list[str], code: str, enabled: bool) -> None:
    assert Options(select=select, ignore=ignore).enabled(code) is enabled


def test_per_file_ignores_match_a_glob() -> None:
    options = Options(per_file_ignores={"vendor/*.glsl": ["C"]})
    assert not options.enabled("C003", "vendor/noise.glsl")
    assert options.enabled("C003", "mine/noise.glsl")


# --- suppressions -----------------------------------------------------------------------------


def test_syntax_error_without_glslang_is_c003_at_its_line() -> None:
    found = lint_source(BROKEN, "x.glsl", Options(glslang=False))
    assert [(f.code, f.line) for f in found] == [("C003", 3)]


def test_an_if_on_a_macro_no_tab_defines_is_c004_and_the_file_is_still_analysed() -> None:
    # SURFACE_CACHE comes from ShaderToy's Common tab: C004 says so, and the rest of the file
    # is linted with it taken as 0 (the #else branch), as C would
    text = (
        "#if SURFACE_CACHE > 0\n#define SCALE 2.0\n#else\n#define SCALE 1.0\n#endif\n"
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    float d = p.x / 0.0;\n"
        "    c = vec4(d * SCALE);\n}\n"
    )
    found = lint_source(text, "x.glsl", Options(select=["C004", "N"], glslang=False))
    assert ("C004", 1) in [(f.code, f.line) for f in found]
    assert any(f.code.startswith("N") and f.line == 7 for f in found), found
    # a syntax error after the #if is reported too, at its own line
    broken = text.replace("c = vec4(d * SCALE);", "c = vec4(d * SCALE)")
    found = lint_source(broken, "x.glsl", Options(select=["C"], glslang=False))
    assert [(f.code, f.line) for f in found] == [("C004", 1), ("C003", 9)]


def test_inline_suppression_on_the_line_silences_that_code() -> None:
    text = BROKEN.replace("}\n", "} // glint: ignore[C003]\n")
    assert lint_source(text, "x.glsl", Options(glslang=False)) == []


def test_suppression_alone_on_a_line_covers_the_next_line() -> None:
    text = BROKEN.replace("}\n", "// glint: ignore[C003]\n}\n")
    assert lint_source(text, "x.glsl", Options(glslang=False)) == []


def test_file_ignore_silences_the_code_everywhere() -> None:
    text = "// glint: file-ignore[C003]\n" + BROKEN
    assert lint_source(text, "x.glsl", Options(glslang=False)) == []


def test_unused_and_unknown_suppressions_are_findings() -> None:
    text = "// glint: file-ignore[C004, Z123]\n" + BROKEN.replace("(1.0)", "(1.0);")
    found = lint_source(text, "x.glsl", Options(glslang=False))
    messages = [f.message for f in found]
    assert codes(found) == ["S001", "S001"]
    assert any("unknown code" in m and "Z123" in m for m in messages)
    assert any("unused suppression of C004" in m for m in messages)


def test_suppression_of_a_code_that_did_not_run_is_not_reported_unused() -> None:
    text = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); } // glint: ignore[C001]\n"
    assert lint_source(text, "x.glsl", Options(glslang=False, ignore=["C001"])) == []


# --- configuration ----------------------------------------------------------------------------


def test_pyproject_table_is_read_from_the_nearest_pyproject(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text(
        '[tool.glint.lint]\nselect = ["C", "N"]\nignore = ["C002"]\ntarget = "webgl2"\n'
        '[tool.glint.lint.per-file-ignores]\n"gen/*.glsl" = ["N"]\n'
    )
    (tmp_path / "shaders").mkdir()
    options, path = load_options(tmp_path / "shaders")
    assert path == tmp_path / "pyproject.toml"
    assert options.select == ["C", "N"] and options.ignore == ["C002"]
    assert options.target == "webgl2" and options.per_file_ignores == {"gen/*.glsl": ["N"]}


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ({"selct": ["N"]}, 'unknown key "selct"'),
        ({"select": "N"}, "expected a list of rule codes"),
        ({"target": "metal"}, 'target = "metal" \\(a string\\): expected one of "shadertoy"'),
    ],
)
def test_bad_configuration_is_one_clear_usage_error(table: dict, message: str) -> None:
    with pytest.raises(UsageError, match=message):
        options_from_table(table, "pyproject.toml")


# --- reading and fixes ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("data", "why"),
    [
        (b"\x89PNG\r\n\x1a\n\0\0\0", "binary data"),
        (b"float x = 1.0;\n\xff\xfe", "not UTF-8 text (invalid byte 0xff on line 2)"),
        (b"float x;\n" * 200_000, "too large to analyse"),
    ],
)
def test_unreadable_bytes_are_one_c005_finding(data: bytes, why: str) -> None:
    result = lint_bytes(data, "x.glsl", Options())
    assert codes(result.findings) == ["C005"] and why in result.findings[0].message


def test_a_byte_of_an_older_encoding_in_a_comment_is_linted_and_kept_by_a_fix() -> None:
    # Real shaders of 2013 carry Latin-1 in comments (`// rotate 180\xb0`); glslang ignores
    # comments, so the file is linted, and a fix writes the byte back as it was.
    data = b"// rotate 18\xb0 /* caf\xe9 */\nvoid f() { vec4 c = texture2D(iChannel0, vec2(0)); }\n"
    result = lint_bytes(data, "x.glsl", Options(select=["P003"], glslang=False), fix=True)
    assert "C005" not in codes(result.findings) and result.fixed == 1
    assert result.encoded() == data.replace(b"texture2D", b"texture")


def test_edits_apply_from_the_end_so_positions_stay_valid() -> None:
    text = "aa bb\ncc dd\n"
    edits = [Edit(1, 1, 1, 3, "x"), Edit(2, 4, 2, 6, "yyy"), Edit(1, 4, 2, 1, "")]
    assert apply_edits(text, edits) == "x cc yyy\n"


# --- reporters --------------------------------------------------------------------------------

FINDINGS = [
    Finding("a.glsl", 2, 9, 2, 18, "P003", "error", "texture2D is not in GLSL ES 3.00",
            Fix("use texture", (Edit(2, 9, 2, 18, "texture"),))),
    Finding("a.glsl", 3, 1, 3, 2, "C003", "error", "unexpected '}'"),
]  # fmt: skip
SOURCES = {"a.glsl": "void f() {\n    c = texture2D(iChannel0, p);\n}\n"}


def test_text_format_has_the_location_the_code_and_a_caret_under_the_span() -> None:
    out = REPORTERS["text"](FINDINGS, SOURCES)
    assert "a.glsl:2:9: P003 texture2D is not in GLSL ES 3.00 [*]" in out
    assert "    2 |     c = texture2D(iChannel0, p);\n" + " " * 16 + "^" * 9 in out


def test_concise_format_is_one_line_per_finding() -> None:
    out = REPORTERS["concise"](FINDINGS, SOURCES)
    assert out.splitlines() == [
        "a.glsl:2:9: P003 texture2D is not in GLSL ES 3.00 [*]",
        "a.glsl:3:1: C003 unexpected '}'",
    ]


def test_json_format_is_the_stable_interface() -> None:
    data = json.loads(REPORTERS["json"](FINDINGS, SOURCES))
    assert list(data[0]) == ["file", "line", "column", "end_line", "end_column", "code",
                             "severity", "message", "certainty", "fix"]  # fmt: skip
    assert data[0]["fix"]["edits"][0] == {
        "line": 2, "column": 9, "end_line": 2, "end_column": 18, "content": "texture"
    }  # fmt: skip
    assert data[1]["fix"] is None


def test_sarif_format_names_the_rules_and_regions() -> None:
    log = json.loads(REPORTERS["sarif"](FINDINGS[1:], SOURCES))
    run = log["runs"][0]
    assert log["version"] == "2.1.0" and run["tool"]["driver"]["rules"][0]["id"] == "C003"
    region = run["results"][0]["locations"][0]["physicalLocation"]["region"]
    assert region == {"startLine": 3, "startColumn": 1, "endLine": 3, "endColumn": 2}


def test_github_format_is_workflow_annotations() -> None:
    out = REPORTERS["github"](FINDINGS[1:], SOURCES)
    assert (
        out == "::error file=a.glsl,line=3,col=1,endLine=3,endColumn=2,title=C003::unexpected '}'\n"
    )


def test_statistics_count_per_code_and_mark_fixable() -> None:
    lines = statistics(FINDINGS + FINDINGS[1:] * 2).splitlines()
    assert lines[0].split() == ["3", "C003", "syntax-error"]
    assert lines[1].split()[:2] == ["1", "P003"] and lines[1].endswith("[*]")


def test_a_fix_that_would_break_the_shader_is_not_applied(monkeypatch: pytest.MonkeyPatch) -> None:
    # A buggy fix cannot be produced by the real rules on purpose, so one is registered here.
    from glint.lint.rules import Rule
    from glint.lint.runner import lint_text

    class BreaksCode(Rule):
        """Finds every `vec4(` and 'fixes' it into a syntax error.

        Why it matters: it does not; it stands for a rule with a bug.
        Example: vec4(1.0)
        Fix: none
        """

        code = "S998"
        name = "breaks-code"
        category = "style"
        fixable = "safe"

        def check(self, ctx):  # type: ignore[no-untyped-def]
            from glint.lint.context import walk

            for node in walk(ctx.tree):
                if node.data == "constructor":
                    edit = ctx.replace(node, "vec4(1.0")
                    yield self.report(ctx, node, "broken", Fix("break it", (edit,)))

    monkeypatch.setitem(REGISTRY, "S998", BreaksCode)
    text = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n"
    result = lint_text(text, "x.glsl", Options(select=["S998", "C003"], glslang=False), fix=True)
    assert result.text == text and result.fixed == 0
    assert result.notes and "fixes not applied" in result.notes[0]


def test_a_byte_order_mark_is_not_a_syntax_error() -> None:
    data = b"\xef\xbb\xbfvoid mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n"
    assert lint_bytes(data, "x.glsl", Options(glslang=False)).findings == []


def test_a_finding_says_how_sure_it_is() -> None:
    """A value that is 0 at a named moment is certain, a range that reaches 0 only possible; the
    certainty travels through json, SARIF and the cache's reader."""
    from glint.lint.cache import finding_from_json
    from glint.lint.options import Options
    from glint.lint.runner import lint_source

    src = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    float a = 1.0 / iTime;\n"  # 0 at the first frame: certain (N011)
        "    float b = 1.0 / sin(fragCoord.x);\n"  # reaches 0 in its range: possible (N005)
        "    fragColor = vec4(a + b);\n"
        "}\n"
    )
    found = lint_source(src, "x.glsl", Options(select=["N005", "N011"], glslang=False))
    sure = {(f.code, f.line): f.certainty for f in found}
    assert sure[("N011", 2)] == "certain" and sure[("N005", 3)] == "possible"
    data = json.loads(REPORTERS["json"](found, {"x.glsl": src}))
    assert [d["certainty"] for d in data] == [f.certainty for f in found]
    assert [finding_from_json(d).certainty for d in data] == [f.certainty for f in found]
    sarif = json.loads(REPORTERS["sarif"](found, {"x.glsl": src}))
    results = sarif["runs"][0]["results"]
    assert [r["properties"]["certainty"] for r in results] == [f.certainty for f in found]
