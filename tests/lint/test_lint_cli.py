"""`glint lint` and `glint rule` as a user runs them: exit codes, formats, directories,
configuration, fixes written back in place, and one clear message for bad usage."""

from __future__ import annotations

import json
import os
import shutil
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


# --- the cache (.glint_cache) and parallel linting ----------------------------------------------

ROOT = Path(__file__).resolve().parents[2]
CORPUS_FILES = sorted((ROOT / "tests" / "corpus" / "lint_mistakes").glob("*.glsl")) + sorted(
    (ROOT / "tests" / "corpus" / "valid").glob("*.glsl")
)


def _entries(tree: Path) -> list[Path]:
    return sorted((tree / ".glint_cache").glob("v1-*/*.json"))


def _plant(entry: Path, message: str, fix: dict[str, object] | None = None) -> None:
    """Rewrite a cache entry to hold one made-up finding: seen in the output only if the
    entry was read."""
    finding = {"file": "a.glsl", "line": 1, "column": 1, "end_line": 1, "end_column": 5,
               "code": "C003", "severity": "error", "message": message, "fix": fix}  # fmt: skip
    entry.write_text(json.dumps({"findings": [finding]}))


def test_a_second_run_reads_the_cache(tree: Path) -> None:
    first = glint("lint", "a.glsl", "--no-glslang", "--format", "json", cwd=tree)
    assert first.returncode == 0 and json.loads(first.stdout) == []
    # beside pyproject.toml, marked as a cache and ignored by git
    assert (tree / ".glint_cache" / "CACHEDIR.TAG").is_file()
    assert (tree / ".glint_cache" / ".gitignore").read_text().splitlines()[-1] == "*"
    [entry] = _entries(tree)
    _plant(entry, "from the cache")
    second = glint("lint", "a.glsl", "--no-glslang", "--format", "json", cwd=tree)
    assert [f["message"] for f in json.loads(second.stdout)] == ["from the cache"]
    assert second.returncode == 1  # the exit status follows the cached findings


def test_changed_content_options_or_no_cache_lint_afresh(tree: Path) -> None:
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    [entry] = _entries(tree)
    _plant(entry, "from the cache")
    # --no-cache neither reads nor writes
    fresh = glint("lint", "a.glsl", "--no-glslang", "--no-cache", cwd=tree)
    assert fresh.returncode == 0 and "from the cache" not in fresh.stdout
    assert _entries(tree) == [entry]
    # other options are another entry
    other = glint("lint", "a.glsl", "--no-glslang", "--select", "ALL", cwd=tree)
    assert other.returncode == 0 and "from the cache" not in other.stdout
    assert len(_entries(tree)) == 2
    # a changed file is another entry: the broken text's syntax error, not the planted finding
    (tree / "a.glsl").write_text(BROKEN)
    changed = glint("lint", "a.glsl", "--no-glslang", "--format", "concise", cwd=tree)
    assert changed.returncode == 1 and "from the cache" not in changed.stdout
    assert changed.stdout.startswith("a.glsl:3:1: C003")
    assert len(_entries(tree)) == 3


def test_fix_never_applies_cached_findings(tree: Path) -> None:
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    [entry] = _entries(tree)
    edit = {"line": 1, "column": 1, "end_line": 1, "end_column": 5, "content": "SENTINEL"}
    _plant(entry, "stale", {"message": "stale fix", "applicability": "safe", "edits": [edit]})
    assert "stale" in glint("lint", "a.glsl", "--no-glslang", cwd=tree).stdout  # planted
    fixed = glint("lint", "a.glsl", "--no-glslang", "--fix", cwd=tree)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert (tree / "a.glsl").read_text() == CLEAN  # linted afresh: nothing to fix


def test_fixed_file_is_cached_as_written(tree: Path) -> None:
    (tree / "t.glsl").write_text(CLEAN.replace("vec4(1.0)", "texture2D(iChannel0, fragCoord)"))
    fixed = glint("lint", "t.glsl", "--no-glslang", "--select", "P003", "--fix", cwd=tree)
    assert fixed.returncode == 0 and "texture(" in (tree / "t.glsl").read_text()
    [entry] = _entries(tree)  # the fixed text's findings (none), keyed by the bytes written
    assert json.loads(entry.read_text()) == {"findings": []}
    _plant(entry, "from the cache")
    again = glint("lint", "t.glsl", "--no-glslang", "--select", "P003", cwd=tree)
    assert "from the cache" in again.stdout


def test_a_fixed_file_keeps_its_mode(tree: Path) -> None:
    shader = tree / "t.glsl"
    shader.write_text(CLEAN.replace("vec4(1.0)", "texture2D(iChannel0, fragCoord)"))
    shader.chmod(0o644)
    fixed = glint("lint", "t.glsl", "--no-glslang", "--select", "P003", "--fix", cwd=tree)
    assert fixed.returncode == 0 and "texture(" in shader.read_text()
    assert shader.stat().st_mode & 0o777 == 0o644  # not the 0600 of a temporary file


FIXABLE = CLEAN.replace("vec4(1.0)", "texture2D(iChannel0, fragCoord)")
FIX = ("--no-glslang", "--no-cache", "--select", "P003", "--fix")


def test_a_fix_keeps_the_byte_order_mark(tree: Path) -> None:
    shader = tree / "t.glsl"
    shader.write_bytes(b"\xef\xbb\xbf" + FIXABLE.encode())
    fixed = glint("lint", "t.glsl", *FIX, cwd=tree)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert shader.read_bytes() == b"\xef\xbb\xbf" + FIXABLE.replace("texture2D", "texture").encode()


def test_a_fix_of_standard_input_keeps_the_byte_order_mark(tree: Path) -> None:
    fixed = subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", "lint", "-", *FIX],
        input=b"\xef\xbb\xbf" + FIXABLE.encode(), capture_output=True, cwd=tree, timeout=120,
    )  # fmt: skip
    assert fixed.returncode == 0, fixed.stderr
    assert fixed.stdout == b"\xef\xbb\xbf" + FIXABLE.replace("texture2D", "texture").encode()


def test_a_fix_writes_through_a_symlink(tree: Path) -> None:
    (tree / "real.glsl").write_text(FIXABLE)
    (tree / "link.glsl").symlink_to("real.glsl")
    fixed = glint("lint", "link.glsl", *FIX, cwd=tree)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert (tree / "link.glsl").is_symlink()
    assert "texture(" in (tree / "real.glsl").read_text()


def test_a_fix_keeps_hard_links(tree: Path) -> None:
    (tree / "t.glsl").write_text(FIXABLE)
    os.link(tree / "t.glsl", tree / "same.glsl")
    fixed = glint("lint", "t.glsl", *FIX, cwd=tree)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert (tree / "t.glsl").stat().st_ino == (tree / "same.glsl").stat().st_ino
    assert "texture(" in (tree / "same.glsl").read_text()


def test_a_fix_refuses_a_read_only_file(tree: Path) -> None:
    shader = tree / "t.glsl"
    shader.write_text(FIXABLE)
    shader.chmod(0o444)
    fixed = glint("lint", "t.glsl", *FIX, cwd=tree)
    assert fixed.returncode == 2
    assert fixed.stderr == (
        "glint: cannot write t.glsl: it is read-only (mode 0444); make it writable (chmod u+w) "
        "or write elsewhere\n"
    )
    assert shader.read_text() == FIXABLE and shader.stat().st_mode & 0o777 == 0o444


@pytest.mark.skipif(os.geteuid() != 0, reason="giving a file to another user needs root")
def test_a_fix_as_root_leaves_the_file_to_its_owner(tree: Path) -> None:
    shader = tree / "theirs.glsl"
    shader.write_text(FIXABLE)
    os.chown(shader, 65534, 65534)
    shader.chmod(0o600)
    fixed = glint("lint", "theirs.glsl", *FIX, cwd=tree)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    after = shader.stat()
    assert (after.st_uid, after.st_gid, after.st_mode & 0o777) == (65534, 65534, 0o600)
    assert "texture(" in shader.read_text()


def test_a_folder_search_skips_the_writers_temporary_files(tree: Path) -> None:
    (tree / "sub" / "b.frag").unlink()
    (tree / ".glint-tmp-x.glsl").write_text(BROKEN)  # left by a killed run
    (tree / "sub" / ".glint-k3x_9abz.frag").write_text(BROKEN)  # an older glint's name
    result = glint("lint", ".", "--no-glslang", "--no-cache", "--format", "concise", cwd=tree)
    assert result.returncode == 0, result.stdout + result.stderr
    assert ".glint-" not in result.stdout


def test_cache_dir_option_and_environment(
    tree: Path, tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch
) -> None:
    elsewhere = tmp_path_factory.mktemp("cache")
    glint("lint", "a.glsl", "--no-glslang", "--cache-dir", str(elsewhere), cwd=tree)
    assert len(list(elsewhere.glob("v1-*/*.json"))) == 1 and _entries(tree) == []
    from_environment = tmp_path_factory.mktemp("environment")
    monkeypatch.setenv("GLINT_CACHE_DIR", str(from_environment))
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    assert len(list(from_environment.glob("v1-*/*.json"))) == 1 and _entries(tree) == []


@pytest.mark.parametrize("glslang", [False, True])
def test_parallel_results_equal_serial_ones_in_order(glslang: bool) -> None:
    if glslang and shutil.which("glslangValidator") is None:
        pytest.skip("glslangValidator not installed")
    assert len(CORPUS_FILES) >= 8
    flags = ["--select", "ALL", "--no-cache", "--format", "json"]
    flags += [] if glslang else ["--no-glslang"]
    files = [str(p) for p in CORPUS_FILES]
    serial = glint("lint", *flags, "--jobs", "1", *files)
    parallel = glint("lint", *flags, "--jobs", "3", *files)
    assert serial.returncode == parallel.returncode == 1, serial.stderr + parallel.stderr
    assert parallel.stdout == serial.stdout
    found = json.loads(serial.stdout)
    order = [files.index(f["file"]) for f in found]
    assert order == sorted(order) and len(set(order)) > 5  # file by file, as given


def test_lint_items_are_the_same_in_workers_and_in_process() -> None:
    from glint.lint.options import Options
    from glint.lint.parallel import chunks, lint_items, worker_count
    from glint.lint.runner import lint_bytes

    items = [(str(p), p.read_bytes()) for p in CORPUS_FILES]
    options = Options(select=["ALL"], glslang=False)
    alone = [lint_bytes(data, name, options) for name, data in items]
    in_workers = lint_items(items, options, jobs=2)
    assert [r.file for r in in_workers] == [name for name, _ in items]
    assert [r.findings for r in in_workers] == [r.findings for r in alone]
    assert any(r.findings for r in alone)
    # a handful of files stays in this process; chunks cover every file once, in order
    assert worker_count(3, jobs=8) == 1 and worker_count(100, jobs=2) == 2
    parts = chunks(items, 2)
    assert [item for part in parts for item in part] == items and len(parts) > 2


@pytest.mark.skipif(shutil.which("glslangValidator") is None, reason="glslangValidator needed")
def test_glslang_errors_of_a_batch_stay_on_their_files(tree: Path) -> None:
    (tree / "x.glsl").write_text(CLEAN.replace("vec4(1.0)", "vec4(undefinedX)"))  # line 2
    (tree / "y.glsl").write_text("\n\n\n" + CLEAN.replace("vec4(1.0)", "vec4(undefinedY)"))
    result = glint("lint", "x.glsl", "a.glsl", "y.glsl", "--select", "C001", "--jobs", "1",
                   "--no-cache", "--format", "json", cwd=tree)  # fmt: skip
    found = json.loads(result.stdout)
    assert [(f["file"], f["line"]) for f in found] == [("x.glsl", 2), ("y.glsl", 5)]
    assert "undefinedX" in found[0]["message"] and "undefinedY" in found[1]["message"]


def test_a_change_to_the_code_or_the_settings_changes_the_key(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from glint.lint import cache
    from glint.lint.options import Options

    source = tmp_path / "lint" / "rule.py"
    source.parent.mkdir()
    source.write_text("X = 1\n")
    monkeypatch.setattr(cache, "_LINT_DIR", source.parent)
    monkeypatch.setattr(cache, "_COMPILER_DIR", tmp_path / "compiler")
    before = cache.code_fingerprint.__wrapped__()
    source.write_text("X = 2\n")
    assert cache.code_fingerprint.__wrapped__() != before
    keys = {
        cache.LintCache(tmp_path, options).key("a.glsl", b"x")
        for options in (Options(), Options(select=["ALL"]), Options(ignore=["N"]),
                        Options(target="webgl2"), Options(glslang=False))
    }  # fmt: skip
    assert len(keys) == 5
    one = cache.LintCache(tmp_path, Options())
    assert len({one.key("a.glsl", b"x"), one.key("b.glsl", b"x"), one.key("a.glsl", b"y")}) == 3


def test_an_unreadable_entry_is_a_miss_and_is_rewritten(tree: Path) -> None:
    glint("lint", "sub/b.frag", "--no-glslang", cwd=tree)
    [entry] = _entries(tree)
    entry.write_text('{"findings": [{"file": ')  # cut short, as by a full disk
    result = glint("lint", "sub/b.frag", "--no-glslang", "--format", "json", cwd=tree)
    assert result.returncode == 1 and json.loads(result.stdout)[0]["code"] == "C003"
    assert json.loads(entry.read_text())["findings"][0]["code"] == "C003"
    assert not list(entry.parent.glob("*.tmp"))  # written atomically: no temporary left


def test_entries_of_other_code_versions_are_removed(tree: Path) -> None:
    old = tree / ".glint_cache" / "v1-0123456789abcdef"
    old.mkdir(parents=True)
    (old / "entry.json").write_text('{"findings": []}')
    keep = tree / ".glint_cache" / "not-a-version"
    keep.mkdir()
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    assert not old.exists() and keep.exists() and len(_entries(tree)) == 1
