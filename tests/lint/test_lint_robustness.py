"""No input crashes the linter: truncated files, binary junk, unbalanced braces, unknown
directives, 10 MB of code, deep nesting. Each gets a diagnostic (exit status 1 from the CLI),
never a traceback. Explicit cases first, then property-based tests over the parser and rules."""

from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from glint.lint.finding import Finding
from glint.lint.options import Options
from glint.lint.rules import all_rules
from glint.lint.runner import MAX_BYTES, UNUSED_SUPPRESSION, LintResult, lint_bytes, lint_text

ROOT = Path(__file__).resolve().parents[2]
VALID = sorted((ROOT / "tests" / "corpus" / "valid").glob("*.glsl"))
LINT_CORPUS = sorted((ROOT / "tests" / "corpus" / "lint").glob("*.glsl"))
MISTAKES = sorted((ROOT / "tests" / "corpus" / "lint_mistakes").glob("*.glsl"))
GLINT = Path(sys.executable).with_name("glint")
HAS_CLI = importlib.util.find_spec("glint.lint.cli") is not None and GLINT.exists()
HAS_GLSLANG = shutil.which("glslangValidator") is not None
OFF = Options(select=["ALL"], glslang=False)  # every rule must survive bad input

DEEP = 25_000  # nesting beyond runner.RECURSION_LIMIT (20000 frames)
HEAD = b"void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
TAIL = b"\n}\n"


def _shader(body: bytes) -> bytes:
    return HEAD + body + TAIL


def _macro_bomb() -> bytes:
    # Each macro uses the previous one twice: 2^30 tokens if expanded naively.
    lines = [b"#define A0 1.0"] + [
        b"#define A%d (A%d + A%d)" % (i, i - 1, i - 1) for i in range(1, 31)
    ]
    return b"\n".join(lines) + b"\n" + _shader(b"fragColor = vec4(A30);")


# name -> (the file's bytes, the codes one of which must be reported)
CASES: dict[str, tuple[Callable[[], bytes], set[str]]] = {
    "truncated": (lambda: _shader(b"fragColor = vec4(")[:-3], {"C003"}),
    "truncated-in-comment": (lambda: HEAD + b"/* unfinished", {"C004"}),
    "binary-junk": (lambda: bytes(range(256)) * 64, {"C005"}),
    "not-utf8": (lambda: _shader(b"float caf\xe9 = 1.0;"), {"C005"}),  # outside a comment
    "png-header": (lambda: b"\x89PNG\r\n\x1a\n" + b"\x00" * 64, {"C005"}),
    "extra-closing-brace": (lambda: _shader(b"fragColor = vec4(1.0);") + b"}\n}\n", {"C003"}),
    "missing-closing-brace": (lambda: HEAD + b"if (true) {\nfragColor = vec4(1.0);\n", {"C003"}),
    "unbalanced-parens": (lambda: _shader(b"fragColor = vec4((1.0);"), {"C003"}),
    "only-braces": (lambda: b"{" * 5000, {"C003", "C006"}),
    "unknown-directive": (lambda: b"#frobnicate 3\n" + _shader(b"fragColor = vec4(1);"), {"C004"}),
    "include": (lambda: b'#include "common.glsl"\n' + _shader(b""), {"C004"}),
    "unterminated-if": (lambda: b"#ifdef FAST\n" + _shader(b""), {"C004"}),
    "error-directive": (lambda: b"#error not for this target\n", {"C004"}),
    "bad-macro-call-in-line": (lambda: b"#define F(x) x\n#line F(\n" + _shader(b""), {"C004"}),
    "macro-bomb": (_macro_bomb, {"C004"}),
    "ten-megabytes": (lambda: _shader(b"fragColor += vec4(0.001);\n" * 400_000), {"C005"}),
    # Nesting: the LALR parser is iterative; the symbol walk, the analyses and the rules recurse
    # (under a raised limit, runner.RECURSION_LIMIT). Past it: C006, never a RecursionError.
    "25000-nested-parens-with-operators": (
        lambda: _shader(b"float x = " + b"(1.0 + " * DEEP + b"1.0" + b")" * DEEP + b";"),
        {"C006"},
    ),
    "25000-nested-calls": (
        lambda: _shader(b"float x = " + b"abs(" * DEEP + b"1.0" + b")" * DEEP + b";"),
        {"C006"},
    ),
    "25000-nested-blocks": (
        lambda: _shader(b"{" * DEEP + b"fragColor = vec4(1.0);" + b"}" * DEEP),
        {"C006"},
    ),
    "25000-nested-ifs": (
        lambda: _shader(
            b"if (fragCoord.x > 0.0) {" * DEEP + b"fragColor = vec4(1.0);" + b"}" * DEEP
        ),
        {"C006"},
    ),
    "30000-term-operator-chain": (
        lambda: _shader(b"float x = 1.0" + b" + 1.0" * 30_000 + b";"),
        {"C006"},
    ),
    "deep-if-expression": (
        lambda: b"#if " + b"(" * DEEP + b"1" + b")" * DEEP + b"\n#endif\n",
        {"C006"},
    ),
    # Each level copies its argument: the expansion cap stops it long before the stack would.
    "3000-nested-macro-calls": (
        lambda: (
            b"#define I(x) (x)\n"
            + _shader(b"float x = " + b"I(" * 3000 + b"1.0" + b")" * 3000 + b";")
        ),
        {"C004", "C006"},
    ),
}


# Seconds each through the API; the CLI run leaves them out (the API covers them).
SLOW = {
    "macro-bomb",
    "25000-nested-parens-with-operators",
    "25000-nested-calls",
    "25000-nested-ifs",
    "30000-term-operator-chain",
}


def _registered() -> set[str]:
    # S001 (unused suppression) is the runner's own finding; not (yet) a registered rule.
    return set(all_rules()) | {UNUSED_SUPPRESSION}


def check_findings(findings: list[Finding], text: str) -> None:
    """What every finding on any input must satisfy."""
    assert isinstance(findings, list)
    lines = text.split("\n")
    codes = _registered()
    for f in findings:
        assert isinstance(f, Finding), f
        assert f.code in codes, f
        assert 1 <= f.line <= len(lines) + 1, (f, len(lines))
        assert f.column >= 1, f
        assert (f.end_line, f.end_column) >= (f.line, f.column), f
        assert f.severity in ("error", "warning", "info"), f
        assert f.message, f


def _lint(data: bytes) -> LintResult:
    result = lint_bytes(data, "x.glsl", OFF)
    text = data.decode("utf-8", errors="replace") if len(data) <= MAX_BYTES else ""
    check_findings(result.findings, text)
    return result


@pytest.mark.parametrize("name", list(CASES))
def test_bad_input_gets_a_diagnostic(name: str) -> None:
    make, expected = CASES[name]
    result = _lint(make())
    codes = {f.code for f in result.findings}
    assert codes & expected, (name, result.findings[:5])
    assert any(f.severity == "error" for f in result.findings)


def test_ten_megabytes_are_refused_before_any_analysis() -> None:
    data = CASES["ten-megabytes"][0]()
    assert len(data) > 10_000_000
    (finding,) = _lint(data).findings
    assert finding.code == "C005" and "too large" in finding.message


def test_a_deep_tree_is_reported_alone() -> None:
    # Rules never see a tree the symbol walk could not follow: C006 is the only finding.
    result = _lint(CASES["25000-nested-blocks"][0]())
    assert [f.code for f in result.findings] == ["C006"]


@pytest.mark.parametrize(
    "body",
    [
        # Bracket nesting up to MAX_NESTING (256) is analysed; deeper is C006 (below).
        b"float x = " + b"(1.0 + " * 250 + b"1.0" + b")" * 250 + b";",
        b"{" * 250 + b"float x = 1.0;" + b"}" * 250,
        b"if (fragCoord.x > 0.0) {" * 120 + b"fragColor.x = 0.5;" + b"}" * 120,
        b"float x = 1.0" + b" + fragCoord.x" * 5000 + b";",
        b"if (fragCoord.x < 0.0) fragColor = vec4(0.0);\n"
        + b"else if (fragCoord.x < 1.0) fragColor = vec4(1.0);\n" * 1000,
        b"float x = " + b"fragCoord.x > 0.0 ? 1.0 : " * 1000 + b"0.0;",
    ],
    ids=["250-parens", "250-blocks", "120-ifs", "5000-terms", "1000-else-ifs", "1000-ternaries"],
)
def test_deep_but_valid_code_is_analysed(body: bytes) -> None:
    # Generated code nests deeply and is valid (glslang takes it): analysed, no error.
    findings = _lint(_shader(b"fragColor = vec4(1.0);\n" + body)).findings
    assert [f for f in findings if f.severity == "error"] == [], findings[:3]


@pytest.mark.parametrize(
    "body",
    [
        b"float x = " + b"(1.0 + " * 5000 + b"1.0" + b")" * 5000 + b";",
        b"{" * 2000 + b"float x = 1.0;" + b"}" * 2000,
        b"if (fragCoord.x > 0.0) {" * 1000 + b"fragColor.x = 0.5;" + b"}" * 1000,
    ],
    ids=["5000-parens", "2000-blocks", "1000-ifs"],
)
def test_bracket_nesting_past_the_limit_is_c006_alone(body: bytes) -> None:
    findings = _lint(_shader(b"fragColor = vec4(1.0);\n" + body)).findings
    assert [f.code for f in findings] == ["C006"]
    assert "levels; glint follows 256" in findings[0].message


def test_parentheses_alone_nest_without_depth() -> None:
    # `((((1.0))))` adds no tree levels: valid GLSL (glslang accepts it), so nothing or C006.
    data = _shader(b"float x = " + b"(" * 5000 + b"1.0" + b")" * 5000 + b";\nfragColor = vec4(x);")
    assert {f.code for f in _lint(data).findings} <= {"C006"}


@pytest.mark.parametrize(
    "data",
    [
        b"",
        b"\n\n   \t\n",
        b"// just a comment",
        b"\xef\xbb\xbf" + _shader(b"fragColor = vec4(1.0);"),  # a BOM
        _shader(b"fragColor = vec4(1.0);").replace(b"\n", b"\r\n"),
        _shader(b"fragColor = vec4(1.0);").replace(b"\n", b"\r"),
        b"#line 0\n" + _shader(b"fragColor = vec4(1.0) x;"),
        b"#line 99999999\n" + _shader(b"fragColor = vec4(1.0) x;"),
        b"#define A B\n#define B A\n" + _shader(b"float A = 1.0; fragColor = vec4(B);"),
        b"#define F(x\n",
        b"#define F(x) x\n" + HEAD + b"fragColor = F(vec4(1.0) ",
        b"#if 1/0\n#endif\n",
        b"#if 99999999999999999999999999\n#endif\n",
        b"#if 1 << 100000000\n#endif\n",
        b"void f() {} \\",
        _shader(b"float x = 1" + b"0" * 5000 + b".0;"),
        _shader(b"float x = a" + b"[0]" * 3000 + b";"),
        _shader(b"float x = a" + b".x" * 3000 + b";"),
        "float é = 1.0; // ✓".encode(),
        b"// glint: ignore[\n// noqa: ZZZ999\n" + _shader(b""),
        b"struct S {" * 2000,
    ],
    ids=lambda d: repr(d[:24]),
)
def test_odd_input_never_raises(data: bytes) -> None:
    _lint(data)
    lint_bytes(data, "x.glsl", OFF, fix=True, unsafe_fixes=True)


# -- the command line -------------------------------------------------------------------------

needs_cli = pytest.mark.skipif(not HAS_CLI, reason="glint lint CLI not installed")


def _run_cli(path: Path, *flags: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(GLINT), "lint", *flags, str(path)],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=path.parent if path.is_file() else path,
    )


def _assert_clean_failure(run: subprocess.CompletedProcess[str], path: Path) -> None:
    assert "Traceback" not in run.stderr and "internal error" not in run.stderr, run.stderr
    assert run.returncode == 1, (run.returncode, run.stdout[-2000:], run.stderr[-2000:])
    assert re.search(rf"{re.escape(path.name)}:\d+:\d+: [A-Z]+\d{{3}} ", run.stdout), run.stdout


@needs_cli
@pytest.mark.parametrize(
    "name",
    ["truncated", "binary-junk", "unknown-directive", "ten-megabytes", "25000-nested-blocks"],
)
def test_cli_exits_1_with_a_diagnostic(name: str, tmp_path: Path) -> None:
    path = tmp_path / f"{name}.glsl"
    path.write_bytes(CASES[name][0]())
    _assert_clean_failure(_run_cli(path, "--no-glslang"), path)


@needs_cli
def test_cli_reports_every_bad_file(tmp_path: Path) -> None:
    # One process for all the cases (each start imports every rule): every file is named in
    # a diagnostic, and the run as a whole exits 1 without a traceback.
    names = [n for n in CASES if n not in SLOW]
    for name in names:
        (tmp_path / f"{name}.glsl").write_bytes(CASES[name][0]())
    run = _run_cli(tmp_path, "--no-glslang", "--format", "concise")
    assert "Traceback" not in run.stderr and "internal error" not in run.stderr, run.stderr
    assert run.returncode == 1, (run.returncode, run.stderr[-2000:])
    for name in names:
        assert re.search(rf"{re.escape(name)}\.glsl:\d+:\d+: ", run.stdout), name


@needs_cli
@pytest.mark.skipif(not HAS_GLSLANG, reason="glslangValidator not installed")
@pytest.mark.parametrize(
    "name",
    [
        "truncated",
        "binary-junk",
        "extra-closing-brace",
        "unknown-directive",
        "ten-megabytes",
        "25000-nested-blocks",
    ],
)
def test_cli_with_glslang_exits_1_with_a_diagnostic(name: str, tmp_path: Path) -> None:
    path = tmp_path / f"{name}.glsl"
    path.write_bytes(CASES[name][0]())
    _assert_clean_failure(_run_cli(path), path)


@needs_cli
@pytest.mark.parametrize("fmt", ["json", "sarif", "github", "concise"])
def test_cli_formats_survive_binary_junk(fmt: str, tmp_path: Path) -> None:
    path = tmp_path / "junk.glsl"
    path.write_bytes(bytes(range(256)) * 4)
    run = _run_cli(path, "--no-glslang", "--format", fmt)
    assert "Traceback" not in run.stderr and "internal error" not in run.stderr, run.stderr
    assert run.returncode == 1 and run.stdout.strip()


# -- properties -------------------------------------------------------------------------------

PROPERTY = settings(
    max_examples=150,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
# Mistakes are in too: they make the rules fire, so their fixes get mutated input as well.
SOURCES = [p.read_text(encoding="utf-8") for p in VALID + LINT_CORPUS + MISTAKES]
SNIPPETS = [
    "float sdSphere(vec3 p, float r) { return length(p) - r; }\n",
    "#define STEPS 64\nfor (int i = 0; i < STEPS; i++) { t += d; }\n",
    "vec3 n = normalize(vec3(e.x, e.y, e.z));\nfloat ndl = max(dot(n, l), 0.0);\n",
    "struct Hit { float t; vec3 n; };\nHit h = Hit(1.0, vec3(0.0));\n",
    "float a[3] = float[3](1.0, 2.0, 3.0);\nswitch (i) { case 0: x = 1.0; break; default: ; }\n",
    "uniform sampler2D tex;\nvec4 c = texture(iChannel0, uv) * pow(x, 2.2);\n",
]
# GLSL-ish tokens, so random sequences get past the lexer into the parser and the rules.
_TOKEN = re.compile(r"\s+|//[^\n]*|/\*.*?\*/|#\w*|\w+|\S", re.S)
VOCABULARY = sorted(
    {t for s in SOURCES[:10] for t in _TOKEN.findall(s) if not t.isspace()} | {"\n", "{", "}"}
)


def _tokens(text: str) -> list[str]:
    return _TOKEN.findall(text)


@st.composite
def mutated(draw: st.DrawFn) -> str:
    """A real shader or snippet, truncated, with characters or tokens deleted, duplicated or
    swapped."""
    text = draw(st.sampled_from(SOURCES + SNIPPETS))
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["truncate", "chars", "tokens", "swap", "insert"]))
        if kind == "truncate":
            text = text[: draw(st.integers(0, len(text)))]
        elif kind == "chars":
            i = draw(st.integers(0, len(text)))
            j = draw(st.integers(i, min(len(text), i + 40)))
            text = text[:i] + (text[i:j] * 2 if draw(st.booleans()) else "") + text[j:]
        else:
            toks = _tokens(text)
            if not toks:
                continue
            i = draw(st.integers(0, len(toks) - 1))
            if kind == "tokens":
                j = draw(st.integers(i, min(len(toks), i + 8)))
                dup = draw(st.booleans())
                toks[i:j] = toks[i:j] * 2 if dup else []
            elif kind == "swap":
                j = draw(st.integers(0, len(toks) - 1))
                toks[i], toks[j] = toks[j], toks[i]
            else:
                toks.insert(i, draw(st.sampled_from(VOCABULARY)))
            text = "".join(toks)
    return text


def _never_raises(text: str, fix: bool = False) -> None:
    result = lint_text(text, "x.glsl", OFF, fix=fix, unsafe_fixes=fix)
    check_findings(result.findings, result.text)
    assert isinstance(result.text, str)


@PROPERTY
@given(st.binary(max_size=2000))
def test_random_bytes(data: bytes) -> None:
    result = lint_bytes(data, "x.glsl", OFF)
    check_findings(result.findings, data.decode("utf-8", errors="replace"))


@PROPERTY
@given(st.text(max_size=500))
def test_random_text(text: str) -> None:
    _never_raises(text)


@PROPERTY
@given(st.lists(st.sampled_from(VOCABULARY), max_size=200))
def test_random_token_sequences(toks: list[str]) -> None:
    _never_raises(" ".join(toks))


@settings(PROPERTY, max_examples=200)
@given(mutated())
def test_mutated_shaders(text: str) -> None:
    _never_raises(text)


@settings(PROPERTY, max_examples=60)
@given(mutated())
def test_mutated_shaders_with_fixes(text: str) -> None:
    _never_raises(text, fix=True)


@pytest.mark.parametrize("path", VALID + LINT_CORPUS, ids=lambda p: p.name)
def test_valid_shaders_draw_no_errors(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    findings = lint_text(text, path.name, OFF).findings
    check_findings(findings, text)
    assert [f for f in findings if f.severity == "error"] == []


# --- scaling: the analyses' work grows linearly with the code's length -------------------------
# Work is counted, not timed: the Python lines the semantic model and the flow analysis execute
# (sys.settrace), and the variables the model stores with the expressions it records. Each
# shape is built with n and 4n statements; linear work grows 4x, quadratic 16x. (Nesting depth
# is another matter: it is capped at 256 levels, C006, and each level costs a scope.)


def _scaling_shape(kind: str, n: int) -> str:
    lines: list[str] = []
    if kind == "declaration-chain":
        lines = ["float a0 = 1.0;"] + [f"float a{i} = a{i - 1} + 1.0;" for i in range(1, n)]
    elif kind == "self-assignments":
        lines = ["float x = 1.0;"] + ["x = x + 1.0;"] * n
    elif kind == "plus-chain":
        lines = [f"float a{i} = {i}.0;" for i in range(n)]
        lines.append("float x = " + " + ".join(f"a{i}" for i in range(n)) + ";")
    elif kind == "and-chain":
        cond = " && ".join(f"fragCoord.x > {i}.0" for i in range(n))
        lines = ["float x = 0.0;", f"if ({cond}) x = 1.0;"]
    elif kind == "else-if-chain":
        lines = [f"float a{i} = 0.0;" for i in range(n)] + ["if (fragCoord.x < 0.0) a0 = 1.0;"]
        lines += [f"else if (fragCoord.x < {i}.0) a{i} = {i}.0;" for i in range(n)]
    elif kind == "ifs-over-uninitialised":
        lines = [f"float a{i};" for i in range(n)]
        lines += [f"if (fragCoord.x > {i}.0) a{i} = 1.0; else a{i} = 2.0;" for i in range(n)]
    elif kind == "sequential-loops":
        lines = [f"float a{i} = 0.0;" for i in range(n)]
        lines += [f"for (int i = 0; i < 4; i++) {{ a{i} += sin(a{i}); }}" for i in range(n)]
    lines.append("fragColor = vec4(1.0);")
    body = "\n    ".join(lines)
    return "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    " + body + "\n}\n"


def _analysis_work(text: str) -> tuple[int, int]:
    """(lines executed, variables stored with recorded expressions) for the semantic model and
    the definite-assignment analysis of `text`."""
    from glint.lint.analysis.flow import function_flows
    from glint.lint.analysis.model import semantic_model
    from glint.lint.runner import build_context

    ctx = build_context(text, "scaling.glsl", OFF)
    assert ctx.tree is not None, ctx.front_end_error
    lines = 0

    def count(frame: object, event: str, arg: object) -> object:
        nonlocal lines
        if event == "line":
            lines += 1
        return count

    previous = sys.gettrace()
    old_limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old_limit, 20_000))
    sys.settrace(count)  # type: ignore[arg-type]
    try:
        model = semantic_model(ctx)
        function_flows(ctx)
    finally:
        sys.settrace(previous)
        sys.setrecursionlimit(old_limit)
    envs = {id(env): env for env in model._env_of.values()}
    return lines, sum(len(env) for env in envs.values())


@pytest.mark.parametrize(
    "kind",
    [
        "declaration-chain",
        "self-assignments",
        "plus-chain",
        "and-chain",
        "else-if-chain",
        "ifs-over-uninitialised",
        "sequential-loops",
    ],
)
def test_analysis_work_grows_linearly(kind: str) -> None:
    small_lines, small_stored = _analysis_work(_scaling_shape(kind, 60))
    large_lines, large_stored = _analysis_work(_scaling_shape(kind, 240))
    # 4x the statements: linear work is 4x plus a constant; quadratic would be ~16x.
    assert large_lines <= 5 * small_lines, (kind, small_lines, large_lines)
    assert large_stored <= 5 * max(small_stored, 1), (kind, small_stored, large_stored)
