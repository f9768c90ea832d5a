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

from glint.lint.finding import Finding

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
    assert set(data[0]) == {"code", "name", "category", "severity", "certainty", "fixable",
                            "summary", "details",
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
    return sorted((tree / ".glint_cache").glob("v*-*/*.json"))


def _plant(entry: Path, message: str, fix: dict[str, object] | None = None) -> None:
    """Rewrite a cache entry to hold one made-up but well-formed finding of its file: seen in
    the output only if the entry was read."""
    content = json.loads(entry.read_text())
    finding = {"file": content["file"], "line": 1, "column": 1, "end_line": 1, "end_column": 5,
               "code": "C003", "severity": "error", "message": message, "certainty": "certain",
               "fix": fix}  # fmt: skip
    entry.write_text(json.dumps({**content, "findings": [finding]}))


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
    assert json.loads(entry.read_text())["findings"] == []
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
    assert len(list(elsewhere.glob("v*-*/*.json"))) == 1 and _entries(tree) == []
    from_environment = tmp_path_factory.mktemp("environment")
    monkeypatch.setenv("GLINT_CACHE_DIR", str(from_environment))
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    assert len(list(from_environment.glob("v*-*/*.json"))) == 1 and _entries(tree) == []


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


# --- configuration and selection: every wrong shape is one clear usage error ------------------


def lint_here(
    args: list[str], tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture
) -> tuple[int, str, str]:
    """`glint lint ARGS` in this process, in `tree`: exit status, stdout and stderr."""
    from glint.compiler.cli import main

    monkeypatch.chdir(tree)
    status = main(["lint", *args])
    out, err = capsys.readouterr()
    return status, out, err


LINT = "[tool.glint.lint]\n"
PFI = "[tool.glint.lint.per-file-ignores]\n"
UNKNOWN = "unknown rule code or prefix"
WRONG_CONFIGURATIONS = [
    # (pyproject.toml, the key = value as the message shows them, what it says was expected)
    ("tool = 3", "tool = 3 (an integer)", "expected a table ([tool])"),
    ("[tool]\nglint = 3", "tool.glint = 3 (an integer)", 'a table ([tool.glint]) with "lint"'),
    ("[tool]\nglint = []", "tool.glint = [] (an array)", "expected a table ([tool.glint])"),
    ("[tool.glint]\nlint = 3", "tool.glint.lint = 3 (an integer)", "expected a table"),
    ("[tool.glint]\nlint = [1]", "tool.glint.lint = [1] (an array)", "select, ignore"),
    ('[tool.glint]\nlint = "N"', 'tool.glint.lint = "N" (a string)', "expected a table"),
    ("[tool.glint]\nlnt = {}", "tool.glint.lnt = {}", 'unknown key "lnt"'),
    ("[tool.glint.lnt]\nselect = 1", "tool.glint.lnt = {select = 1}", 'did you mean "lint"?'),
    (LINT + 'select = "N001"', 'select = "N001" (a string)', "a list of rule codes"),
    (LINT + "select = [1]", "select = [1] (an array)", "1 is an integer"),
    (LINT + 'select = ["N", true]', "select = [", "true is a boolean"),
    (LINT + "select = [[]]", "select = [[]] (an array)", "[] is an array"),
    (LINT + "select = [{a = 1}]", "select = [{a = 1}]", "{a = 1} is a table"),
    (LINT + "select = [1979-05-27]", "select = [1979-05-27]", "is a date"),
    (LINT + "select = []", "select = [] (an array)", "an empty list selects no rule"),
    (LINT + 'select = [""]', 'select = [""]', 'an empty rule code ""'),
    (LINT + 'select = ["Q123"]', 'select = ["Q123"]', UNKNOWN + ' "Q123"'),
    (LINT + 'select = ["P9"]', 'select = ["P9"]', UNKNOWN + ' "P9"'),
    (LINT + "ignore = {}", "ignore = {} (a table)", "a list of rule codes"),
    (LINT + "ignore = 1.5", "ignore = 1.5 (a float)", "a list of rule codes"),
    (LINT + 'ignore = ["N", "X1"]', 'ignore = ["N", "X1"]', UNKNOWN + ' "X1"'),
    (LINT + 'sellect = ["N"]', 'tool.glint.lint.sellect = ["N"]', 'did you mean "select"?'),
    (LINT + "target = 3", "target = 3 (an integer)", 'one of "shadertoy", "webgl2"'),
    (LINT + 'target = ["webgl2"]', 'target = ["webgl2"] (an array)', "one of"),
    (LINT + 'target = "metal"', 'target = "metal" (a string)', "one of"),
    (LINT + "per-file-ignores = []", "per-file-ignores = [] (an array)", "a table of file pattern"),
    (LINT + 'per-file-ignores = "N"', 'per-file-ignores = "N" (a string)', "a table of"),
    (PFI + '"a.glsl" = "N"', 'per-file-ignores."a.glsl" = "N" (a string)', "a list of rule codes"),
    (PFI + '"a b/*.glsl" = [true]', 'per-file-ignores."a b/*.glsl" = [true]', "true is a boolean"),
    (PFI + 'x = ["ZZ1"]', 'per-file-ignores.x = ["ZZ1"]', UNKNOWN + ' "ZZ1"'),
    (PFI + "x = {N = 1}", "per-file-ignores.x = {N = 1} (a table)", "a list of rule codes"),
]


@pytest.mark.parametrize(("toml", "shown", "expected"), WRONG_CONFIGURATIONS)
def test_every_wrong_configuration_is_one_usage_error_naming_file_key_value_and_expectation(
    tree: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture,
    toml: str,
    shown: str,
    expected: str,
) -> None:
    (tree / "pyproject.toml").write_text(toml + "\n")
    status, out, err = lint_here(["a.glsl", "--no-cache"], tree, monkeypatch, capsys)
    assert status == 2 and out == "", err
    assert err.startswith(f"glint: {tree.resolve() / 'pyproject.toml'}: "), err
    assert shown in err and expected in err, err
    assert "internal error" not in err and len(err.splitlines()) == 1


def test_a_configuration_that_leaves_no_rule_is_a_usage_error(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture
) -> None:
    (tree / "pyproject.toml").write_text('[tool.glint.lint]\nignore = ["ALL"]\n')
    status, out, err = lint_here(["sub/b.frag", "--no-cache"], tree, monkeypatch, capsys)
    assert status == 2 and out == ""
    assert err == (
        "glint: no rule is left to run: select DEFAULT (the default), ignore ALL "
        f"({tree.resolve() / 'pyproject.toml'}); select a rule that is not ignored, "
        "e.g. --select DEFAULT\n"
    )
    # a flag that selects a rule again makes it a valid run: the most specific pattern wins
    status, out, err = lint_here(
        ["sub/b.frag", "--no-cache", "--no-glslang", "--select", "C003"], tree, monkeypatch, capsys
    )
    assert status == 1 and "C003" in out and err == ""


@pytest.mark.parametrize(
    ("flags", "message"),
    [
        (["--select", ""], "glint: --select: no rule code given"),
        (["--select", ","], "glint: --select: no rule code given"),
        (["--select", " , "], "glint: --select: no rule code given"),
        (["--select", "C", "--ignore", "C"], "no rule is left to run: select C (--select), "
                                              "ignore C (--ignore)"),
        (["--ignore", "ALL"], "no rule is left to run: select DEFAULT (the default), "
                              "ignore ALL (--ignore)"),
        (["--select", "N001", "--ignore", "N001"], "no rule is left to run"),
        (["--select", "C003,Q1"], "glint: --select: unknown rule code or prefix 'Q1'"),
        (["--ignore", "N001,XY"], "glint: --ignore: unknown rule code or prefix 'XY'"),
        (["--select", "P9"], "glint: --select: unknown rule code or prefix 'P9'"),
    ],
)  # fmt: skip
def test_a_selection_of_no_rule_or_an_unknown_code_is_a_usage_error(
    tree: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture,
    flags: list[str],
    message: str,
) -> None:
    # the broken file: a selection that ran nothing would call it "All clean"
    status, out, err = lint_here(["sub/b.frag", "--no-cache", *flags], tree, monkeypatch, capsys)
    assert status == 2 and out == "" and message in err, err
    assert "All clean" not in out and len(err.splitlines()) == 1


def test_an_empty_ignore_ignores_nothing(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture
) -> None:
    status, out, _ = lint_here(
        ["sub/b.frag", "--no-cache", "--no-glslang", "--ignore", ""], tree, monkeypatch, capsys
    )
    assert status == 1 and "C003" in out


def test_rule_codes_are_read_without_importing_the_rules_and_match_them() -> None:
    from glint.lint.options import default_codes
    from glint.lint.rules import all_rules, rule_codes

    assert rule_codes() == set(all_rules())
    assert default_codes()  # an empty DEFAULT would make `enables_some_rule` wrong


# --- report formats: a file name or a message can neither forge a line nor drive a terminal ----

HOSTILE = "x\n::error file=evil.glsl::pwned,100%\x1b[31m.glsl"  # a real (if odd) file name


def _github_unescape(value: str) -> str:
    """What GitHub's runner reads back from an escaped property value."""
    for escaped, char in (("%0D", "\r"), ("%0A", "\n"), ("%3A", ":"), ("%2C", ","), ("%25", "%")):
        value = value.replace(escaped, char)
    return value


def test_github_format_escapes_a_file_name_that_would_inject_a_workflow_command(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture
) -> None:
    (tree / HOSTILE).write_text(BROKEN)
    args = [HOSTILE, "--no-cache", "--no-glslang", "--format", "github"]
    status, out, err = lint_here(args, tree, monkeypatch, capsys)
    assert status == 1 and err == ""
    [line] = out.splitlines()  # one finding, one command: nothing injected
    assert line == (
        "::error file=x%0A%3A%3Aerror file=evil.glsl%3A%3Apwned%2C100%25\x1b[31m.glsl,"
        "line=3,col=1,endLine=3,endColumn=2,title=C003::unexpected '}', expected one of "
        "';', ',', '(', an operator"
    )
    properties = line.split("::")[1].split(" ", 1)[1]
    values = dict(item.split("=", 1) for item in properties.split(","))
    assert _github_unescape(values["file"]) == HOSTILE


def test_github_format_escapes_the_message_and_every_property() -> None:
    from glint.lint.reporters import REPORTERS

    finding = Finding("a,b:c.glsl", 1, 1, 1, 2, "N001", "info", "50%\r\nmore\n::warning::x")
    assert REPORTERS["github"]([finding], {}) == (
        "::notice file=a%2Cb%3Ac.glsl,line=1,col=1,endLine=1,endColumn=2,title=N001::"
        "50%25%0D%0Amore%0A::warning::x\n"
    )


@pytest.mark.parametrize("format", ["text", "concise"])
def test_text_formats_show_control_characters_of_a_file_name_escaped(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture, format: str
) -> None:
    (tree / HOSTILE).write_text(BROKEN)
    args = [HOSTILE, "--no-cache", "--no-glslang", "--format", format]
    status, out, _ = lint_here(args, tree, monkeypatch, capsys)
    assert status == 1 and "\x1b" not in out
    shown = "x\\n::error file=evil.glsl::pwned,100%\\x1b[31m.glsl"
    assert out.splitlines()[0].startswith(f"{shown}:3:1: C003 unexpected '}}'")
    # the finding's line, for text the excerpt and its caret, then the summary: nothing forged
    assert len(out.splitlines()) == (4 if format == "text" else 2)


def test_text_excerpt_shows_control_characters_of_the_source_as_pictures_under_the_caret(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture
) -> None:
    (tree / "esc.glsl").write_bytes(BROKEN.replace("}", "} // \x1b[2J\rX\x7f", 1).encode())
    args = ["esc.glsl", "--no-cache", "--no-glslang"]
    status, out, _ = lint_here(args, tree, monkeypatch, capsys)
    assert status == 1 and "\x1b" not in out and "\r" not in out and "\x7f" not in out
    assert out.splitlines()[1:3] == ["    3 | } // \u241b[2J\u240dX\u2421", "        ^"]
    # a CRLF file's line ends are not shown
    (tree / "crlf.glsl").write_bytes(BROKEN.replace("\n", "\r\n").encode())
    status, out, _ = lint_here(
        ["crlf.glsl", "--no-cache", "--no-glslang"], tree, monkeypatch, capsys
    )
    assert status == 1 and out.splitlines()[1] == "    3 | }"


def test_text_format_escapes_control_characters_of_a_message() -> None:
    from glint.lint.reporters import REPORTERS

    finding = Finding("a.glsl", 1, 1, 1, 2, "N001", "warning", "bad\nb.glsl:9:9: N002 \x1b]0;x\x07")
    out = REPORTERS["concise"]([finding], {})
    assert out == "a.glsl:1:1: N001 bad\\nb.glsl:9:9: N002 \\x1b]0;x\\x07\n"


# --- the cache trusts only what it wrote for this file ------------------------------------------


def glint_bounded(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    """`glint` in a child of at most 1 GiB of memory and 60 s: a cache entry read without end
    fails the test instead of the machine."""
    import resource

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))

    return subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", *args],
        capture_output=True, text=True, cwd=cwd, timeout=60, preexec_fn=limit,
    )  # fmt: skip


def _corrupt(entry: Path, change: object) -> None:
    content = json.loads(entry.read_text())
    change(content)  # type: ignore[operator]
    entry.write_text(json.dumps(content))


def _set(field: str, value: object) -> object:
    return lambda content: content["findings"][0].__setitem__(field, value)


@pytest.mark.parametrize(
    "change",
    [
        _set("line", "3"),  # crashed the text reporter
        _set("severity", "fatal"),  # crashed the SARIF and GitHub reporters
        _set("line", 0),
        _set("line", 99),  # beyond the file's 3 lines
        _set("line", True),
        _set("line", 3.0),
        _set("column", -1),
        _set("end_line", 2),  # ends before it starts
        _set("end_column", 10**30),
        _set("code", "Z999"),
        _set("code", 3),
        _set("message", None),
        _set("file", "other.glsl"),
        _set("fix", "none"),
        _set("fix", {"message": "m", "applicability": "risky", "edits": []}),
        _set("fix", {"message": "m", "applicability": "safe", "edits": [{"line": 1}]}),
        _set("extra", 1),
        lambda content: content["findings"][0].pop("fix"),
        lambda content: content["findings"].append([]),
        lambda content: content.__setitem__("findings", {}),
        lambda content: content.__setitem__("sha256", "0" * 64),
        lambda content: content.__setitem__("file", "a.glsl"),
        lambda content: content["settings"].__setitem__("select", ["ALL"]),
        lambda content: content.__setitem__("format", "v1"),
        lambda content: content.pop("settings"),
    ],
)
def test_an_entry_that_is_json_but_wrong_is_a_miss_and_is_rewritten(
    tree: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture, change: object
) -> None:
    for format in ("text", "sarif", "github", "json"):
        args = ["sub/b.frag", "--no-glslang", "--jobs", "1", "--format", format]
        fresh = lint_here([*args, "--no-cache"], tree, monkeypatch, capsys)
        assert lint_here(args, tree, monkeypatch, capsys) == fresh
        [entry] = _entries(tree)  # the format is no setting: one entry for all of them
        written = entry.read_text()
        _corrupt(entry, change)
        assert lint_here(args, tree, monkeypatch, capsys) == fresh == (1, fresh[1], "")
        assert entry.read_text() == written  # linted afresh and stored again


def test_another_files_entry_copied_over_a_key_is_not_reported_as_this_ones(tree: Path) -> None:
    glint("lint", "a.glsl", "sub/b.frag", "--no-glslang", cwd=tree)
    entries = {json.loads(e.read_text())["file"]: e for e in _entries(tree)}
    entries["sub/b.frag"].replace(entries["a.glsl"])  # b's findings under a's key
    result = glint("lint", "a.glsl", "--no-glslang", "--format", "json", cwd=tree)
    assert (result.returncode, json.loads(result.stdout)) == (0, [])


def test_an_entry_of_other_content_or_settings_is_not_trusted(tree: Path) -> None:
    # a.glsl's entry of the clean text, copied over the key of its broken text
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    [clean] = _entries(tree)
    (tree / "a.glsl").write_text(BROKEN)
    glint("lint", "a.glsl", "--no-glslang", cwd=tree)
    [broken] = [e for e in _entries(tree) if e != clean]
    clean.replace(broken)
    result = glint("lint", "a.glsl", "--no-glslang", "--format", "concise", cwd=tree)
    assert result.returncode == 1 and result.stdout.startswith("a.glsl:3:1: C003")
    # the entry of --select S (no finding) copied over the key of the default settings
    glint("lint", "a.glsl", "--no-glslang", "--select", "S", cwd=tree)
    [quiet] = [
        e for e in _entries(tree) if json.loads(e.read_text())["settings"]["select"] == ["S"]
    ]
    quiet.replace(broken)
    result = glint("lint", "a.glsl", "--no-glslang", "--format", "concise", cwd=tree)
    assert result.returncode == 1 and result.stdout.startswith("a.glsl:3:1: C003")


@pytest.mark.parametrize("kind", ["/dev/zero", "fifo", "folder", "link to an entry", "huge"])
def test_an_entry_that_is_no_regular_file_or_too_large_is_a_miss_and_is_replaced(
    tree: Path, kind: str
) -> None:
    args = ("lint", "sub/b.frag", "--no-glslang", "--format", "json")
    glint(*args, cwd=tree)
    [entry] = _entries(tree)
    good = entry.read_text()
    other = tree / "planted.json"
    other.write_text(good.replace("unexpected", "planted"))
    entry.unlink()
    if kind == "/dev/zero":
        entry.symlink_to("/dev/zero")  # read to the end, it would exhaust memory
    elif kind == "fifo":
        os.mkfifo(entry)  # opened for reading, it would wait for a writer forever
    elif kind == "folder":
        entry.mkdir()
        (entry / "x").write_text("x")
    elif kind == "link to an entry":
        entry.symlink_to(other)  # well formed, but an entry is never followed
    else:
        with entry.open("w") as out:  # well formed, but past the size limit
            out.write(good[:-1] + " " * (32 << 20) + "}")
    result = glint_bounded(*args, cwd=tree)
    assert result.returncode == 1 and result.stderr == ""
    assert "planted" not in result.stdout and json.loads(result.stdout)[0]["code"] == "C003"
    assert not entry.is_symlink() and entry.is_file() and entry.read_text() == good
    assert other.read_text() == good.replace("unexpected", "planted")  # a link's target kept


def test_an_entry_nested_beyond_the_json_parser_is_a_miss(tree: Path) -> None:
    glint("lint", "sub/b.frag", "--no-glslang", cwd=tree)
    [entry] = _entries(tree)
    entry.write_text("[" * 200_000 + "]" * 200_000)
    result = glint("lint", "sub/b.frag", "--no-glslang", "--format", "concise", cwd=tree)
    assert result.returncode == 1 and result.stdout.startswith("sub/b.frag:3:1: C003")
    assert result.stderr == ""


def test_the_code_fingerprint_covers_every_source_lint_depends_on(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import ast

    from glint.lint import cache

    root = Path(cache.__file__).resolve().parents[1]  # the folder that holds lint/, compiler/
    roots = cache.fingerprint_roots()
    assert all(r.exists() for r in roots), [r for r in roots if not r.exists()]
    for needed in ("lint", "compiler/glsl", "compiler/target", "compiler/errors.py"):
        assert root / needed in roots
    assert root / "lint" / "precision.json" in (root / "lint").rglob("*.json")

    # every compiler module that lint's modules import, directly or through others
    def imports(path: Path) -> set[str]:
        found = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                found.add(node.module)
            elif isinstance(node, ast.Import):
                found.update(alias.name for alias in node.names)
        return {name for name in found if name.startswith("glint.compiler.")}

    def source(module: str) -> Path:
        path = root / module.removeprefix("glint.").replace(".", "/")
        return path / "__init__.py" if path.is_dir() else path.with_suffix(".py")

    todo = set().union(*(imports(p) for p in (root / "lint").rglob("*.py")))
    seen: set[str] = set()
    while todo:
        module = todo.pop()
        seen.add(module)
        todo |= imports(source(module)) - seen
    # writing a fixed file back does not change a finding
    outside = {m for m in seen if not any(source(m).is_relative_to(r) for r in roots)} - {
        "glint.compiler.files"
    }
    assert not outside and "glint.compiler.target.shadertoy" in seen

    # a change to the ShaderToy prelude's folder changes the fingerprint
    (tmp_path / "lint").mkdir()
    (tmp_path / "compiler" / "target").mkdir(parents=True)
    prelude = tmp_path / "compiler" / "target" / "shadertoy.py"
    prelude.write_text("PRELUDE = 1\n")
    monkeypatch.setattr(cache, "_LINT_DIR", tmp_path / "lint")
    monkeypatch.setattr(cache, "_COMPILER_DIR", tmp_path / "compiler")
    before = cache.code_fingerprint.__wrapped__()
    prelude.write_text("PRELUDE = 2\n")
    assert cache.code_fingerprint.__wrapped__() != before


def test_the_settings_name_the_version_that_glslang_prints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from glint.lint import cache

    fake = tmp_path / "glslangValidator"
    fake.write_text("#!/bin/sh\necho 'Glslang Version: 11:12.0.0'\n")
    fake.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    first = cache._glslang_identity.__wrapped__()
    stamp = fake.stat()
    # a wrapper script that now runs another glslang: same path, size and time
    fake.write_text("#!/bin/sh\necho 'Glslang Version: 11:15.0.0'\n")
    os.utime(fake, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
    assert fake.stat().st_size == stamp.st_size
    assert cache._glslang_identity.__wrapped__() != first


def test_random_json_as_an_entry_never_changes_the_output(tmp_path: Path) -> None:
    """Whatever JSON-ish bytes an entry holds, `glint lint` says what an uncached run says."""
    import contextlib
    import io

    from hypothesis import HealthCheck, given, settings
    from hypothesis import strategies as st

    from glint.compiler.cli import main

    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "b.glsl").write_text(BROKEN)
    args = ["lint", "b.glsl", "--no-glslang", "--jobs", "1"]

    def run(*extra: str) -> tuple[int, str, str]:
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main([*args, *extra])
        return status, out.getvalue(), err.getvalue()

    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(tmp_path)
        uncached = run("--no-cache")
        assert uncached[0] == 1 and "C003" in uncached[1]
        run()
        [entry] = _entries(tmp_path)
        written = entry.read_bytes()
        true = json.loads(written)

        leaves = st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=8)
        values = st.recursive(
            leaves,
            lambda c: st.lists(c, max_size=3) | st.dictionaries(st.text(max_size=8), c, max_size=3),
            max_leaves=12,
        )
        field = st.sampled_from(sorted(true["findings"][0]))
        finding = st.dictionaries(field, values, min_size=1) | st.fixed_dictionaries(
            {key: values for key in true["findings"][0]}
        )
        envelope = st.fixed_dictionaries({
            "format": st.just(true["format"]) | values,
            "file": st.just(true["file"]) | values,
            "sha256": st.just(true["sha256"]) | values,
            "settings": st.just(true["settings"]) | values,
            "findings": st.lists(finding | values, min_size=1, max_size=3),
        })  # fmt: skip
        document = (values | envelope).map(lambda v: json.dumps(v).encode())

        @settings(max_examples=100, deadline=None, suppress_health_check=list(HealthCheck))
        @given(document | st.binary(max_size=64))
        def check(content: bytes) -> None:
            entry.write_bytes(content)
            assert run() == uncached
            assert entry.read_bytes() == written  # the entry was rewritten from the fresh run

        check()


def test_a_missing_file_name_is_shown_on_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    """A file name holding a line feed is quoted escaped, so the message stays one line."""
    from glint.compiler.cli import main

    assert main(["lint", "no\nsuch\x1b.glsl"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no\\nsuch\\x1b.glsl" in err


def test_a_fifo_or_a_device_named_to_lint_is_refused_unread(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A FIFO would block the run and /dev/zero never ends: both are named for what they are."""
    from glint.compiler.cli import main

    fifo = tmp_path / "pipe.glsl"
    os.mkfifo(fifo)
    for path in (str(fifo), "/dev/zero"):
        assert main(["lint", "--no-cache", path]) == 2
        assert "not a regular file" in capsys.readouterr().err


def test_a_bug_on_one_file_does_not_end_the_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """glint failing on one file (a bug of its own: no real input is known to cause one, so the
    fault is planted) is that file's note; the other files are still linted and reported, the
    command exits 2 and nothing of the failed file is cached."""
    from glint.compiler.cli import main
    from glint.lint import parallel

    bad = "void mainImage(out vec4 c, in vec2 p) { c = texture2D(iChannel0, p); }\n"
    (tmp_path / "a.glsl").write_text(bad)
    (tmp_path / "b.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n")
    real = parallel.lint_bytes

    def failing(data: bytes, name: str, *args: object) -> object:
        if name.endswith("b.glsl"):
            raise ZeroDivisionError("planted")
        return real(data, name, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(parallel, "lint_bytes", failing)
    cache = tmp_path / "cache"
    assert main(["lint", "--cache-dir", str(cache), "-j", "1", str(tmp_path)]) == 2
    out, err = capsys.readouterr()
    assert "a.glsl:1:" in out and "P003" in out  # the other file's finding is reported
    assert "b.glsl: internal error: ZeroDivisionError: planted" in err
    monkeypatch.setattr(parallel, "lint_bytes", real)  # the bug fixed: b.glsl is linted afresh
    assert main(["lint", "--cache-dir", str(cache), "-j", "1", str(tmp_path)]) == 1
    assert "internal error" not in capsys.readouterr().err


def test_a_syntax_error_is_reported_when_only_c003_is_selected(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """C003 leaves a line to glslang's C001 only where C001 is reported: with --select C003 a
    file that does not parse is never "All clean"."""
    from glint.compiler.cli import main

    broken = tmp_path / "broken.glsl"
    broken.write_text("void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0)\n}\n")
    assert main(["lint", "--no-cache", "--select", "C003", str(broken)]) == 1
    assert "C003" in capsys.readouterr().out
    assert main(["lint", "--no-cache", str(broken)]) == 1  # by default glslang's C001 says it
    out = capsys.readouterr().out
    assert "C001" in out and "C003" not in out
