"""`glint lint` and `glint rule` as a user runs them: exit codes, formats, directories,
configuration, fixes written back in place, and one clear message for bad usage."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

CLEAN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(1.0);\n}\n"
BROKEN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(1.0)\n}\n"


def glint(*args: str, cwd: Path | None = None, stdin: str = "") -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", *args],
        capture_output=True, text=True, cwd=cwd, input=stdin, timeout=120,
    )  # fmt: skip


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "a.glsl").write_text(CLEAN)
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "b.frag").write_text(BROKEN)
    (tmp_path / "sub" / "notes.txt").write_text("not a shader {")
    return tmp_path


def test_clean_file_exits_0(tree: Path) -> None:
    result = glint("lint", "a.glsl", cwd=tree)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "All clean" in result.stdout


def test_directory_is_searched_for_shader_extensions_and_findings_exit_1(tree: Path) -> None:
    result = glint("lint", ".", "--format", "concise", cwd=tree)
    assert result.returncode == 1
    lines = [line for line in result.stdout.splitlines() if line.startswith("sub/")]
    assert lines and all(line.startswith("sub/b.frag:3:") for line in lines)
    assert "notes.txt" not in result.stdout and result.stderr == ""


def test_json_output_parses_and_has_no_summary(tree: Path) -> None:
    result = glint("lint", "sub/b.frag", "--format", "json", "--no-glslang", cwd=tree)
    data = json.loads(result.stdout)
    assert result.returncode == 1 and data[0]["code"] == "C003" and data[0]["line"] == 3


def test_configuration_in_pyproject_is_honoured(tree: Path) -> None:
    (tree / "pyproject.toml").write_text('[tool.glint.lint]\nignore = ["C"]\n')
    assert glint("lint", ".", cwd=tree).returncode == 0


def test_command_line_select_overrides_the_configuration(tree: Path) -> None:
    (tree / "pyproject.toml").write_text('[tool.glint.lint]\nignore = ["C"]\n')
    result = glint("lint", ".", "--select", "C003", "--no-glslang", cwd=tree)
    assert result.returncode == 1 and "C003" in result.stdout


def test_statistics(tree: Path) -> None:
    result = glint("lint", ".", "--statistics", "--no-glslang", cwd=tree)
    assert result.stdout.splitlines()[0].split() == ["1", "C003", "syntax-error"]


def test_stdin(tree: Path) -> None:
    result = glint("lint", "-", "--no-glslang", "--format", "concise", cwd=tree, stdin=BROKEN)
    assert result.returncode == 1 and result.stdout.startswith("<stdin>:3:1: C003")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["lint", "missing.glsl"], "missing.glsl: no such file or directory"),
        (["lint", "a.glsl", "--select", "Q123"], "unknown rule code or prefix 'Q123'"),
        (["lint", "a.glsl", "--unsafe-fixes"], "--unsafe-fixes needs --fix"),
        (["rule", "Z999"], "unknown rule 'Z999'"),
        (["rule"], "give a rule code"),
    ],
)
def test_usage_errors_exit_2_with_one_line(tree: Path, args: list[str], message: str) -> None:
    result = glint(*args, cwd=tree)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_bad_configuration_exits_2(tree: Path) -> None:
    (tree / "pyproject.toml").write_text('[tool.glint.lint]\nselect = "N"\n')
    result = glint("lint", "a.glsl", cwd=tree)
    assert result.returncode == 2 and "expected a list of rule codes" in result.stderr


def test_rule_explains_itself() -> None:
    result = glint("rule", "C003")
    assert result.returncode == 0
    assert result.stdout.startswith("C003 syntax-error (correctness, error)")
    for head in ("Why is this bad?", "Example:", "Use instead:", "Fix safety:", "References:"):
        assert f"\n{head}\n" in result.stdout, head


def test_rule_all_json_lists_every_rule_with_its_docs() -> None:
    from glint.lint.rules import all_rules

    data = json.loads(glint("rule", "--all", "--json").stdout)
    assert [r["code"] for r in data] == list(all_rules())
    assert set(data[0]) == {"code", "name", "category", "severity", "fixable", "summary", "details",
                            "why", "example", "fix_title", "fix", "fix_safety",
                            "references", "runs", "on_real_shaders"}  # fmt: skip
    runs = {r["code"]: r["runs"] for r in data}
    assert runs == {c: "default" if r.default else "opt-in" for c, r in all_rules().items()}
