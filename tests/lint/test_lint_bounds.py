"""Bounded time and memory on runaway input, and no internal error from any input.

Each generated input (most of them ~100 KB) is linted by a process of its own under an
address-space limit and a wall-clock limit; then the same guarantees are fuzzed in-process
with hypothesis. What the audit of issue 25 found, each a case here: two thousand nested
brace-less `for`s took 56 s and 2.2 GB; `x = y = x = ...` ten thousand times ran past 300 s; a
chain of a thousand `#define`s took 4.3 GB in the preprocessor; a doubling macro made
glslangValidator grow without limit; a `×` outside a comment was an internal error.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import glint
from glint.compiler.errors import GlintError
from glint.lint.finding import Finding
from glint.lint.options import Options
from glint.lint.rules import all_rules
from glint.lint.runner import UNUSED_SUPPRESSION, lint_bytes

ROOT = Path(__file__).resolve().parents[2]
GLINT = Path(sys.executable).with_name("glint")
HAS_GLSLANG = shutil.which("glslangValidator") is not None
needs_glslang = pytest.mark.skipif(not HAS_GLSLANG, reason="glslangValidator is not installed")
needs_rlimit = pytest.mark.skipif(os.name != "posix", reason="the limits are set with setrlimit")

# The bounds. On this project's slowest machine (2 shared cores) every case below takes under
# 6 s and 200 MB; the runaways they stand for took minutes (quadratic: 56 s for 2,000 nested
# loops, past 300 s for 10,000 chained `=`) or gigabytes (exponential: 4.3 GB for 1,000
# #defines, unbounded for glslang). Generous, so that a loaded machine passes and a regression
# of that kind fails by far.
SECONDS = 30.0
MEMORY_BYTES = 1536 << 20  # address space of the whole linting process

HEAD = (
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "    float x = 0.0;\n    float y = 1.0;\n    bool b = fragCoord.x > 0.5;\n"
)
TAIL = "\n    fragColor = vec4(x, y, 0.0, 1.0);\n}\n"


def _shader(body: str) -> str:
    return HEAD + body + TAIL


def _defines(levels: int, body: str, use: str) -> str:
    """`#define A0 y` and each next macro made of the one before (`{p}`); A<levels-1> used."""
    lines = ["#define A0 y"] + [
        f"#define A{i} {body.format(p=f'A{i - 1}')}" for i in range(1, levels)
    ]
    return "\n".join(lines) + "\n" + _shader(use.format(top=f"A{levels - 1}"))


_FAT = " x += y * 2.0; y = sin(x) * cos(y) + pow(abs(x), 2.0); b = x < y;"

# name -> (the input, the codes of which one must be reported; empty: analysed, any result)
CASES: dict[str, tuple[Callable[[], str], set[str]]] = {
    # Statements nested in statements, braces or none: quadratic in the analyses of loops.
    "2000-nested-for": (
        lambda: _shader("for (int i = 0; i < 2; i++) " * 2000 + "x += 1.0;"),
        {"C006"},
    ),
    "5000-nested-for": (
        lambda: _shader("for (int i = 0; i < 2; i++) " * 5000 + "x += 1.0;"),
        {"C006"},
    ),
    "5000-nested-while": (lambda: _shader("while (b) " * 5000 + "x += 1.0;"), {"C006"}),
    "5000-nested-if": (lambda: _shader("if (b) " * 5000 + "x += 1.0;"), {"C006"}),
    "3000-nested-do": (
        lambda: _shader("do " * 3000 + "x += 1.0;" + " while (b);" * 3000),
        {"C006"},
    ),
    "64-nested-loops-100KB": (
        lambda: _shader(("for (int i = 0; i < 2; i++) {" + _FAT * 20) * 64 + "}" * 64),
        set(),
    ),
    "65-nested-loops": (
        lambda: _shader("for (int i = 0; i < 2; i++) {" * 65 + "x += 1.0;" + "}" * 65),
        {"C006"},
    ),
    "250-nested-ifs-100KB": (lambda: _shader(("if (b) {" + _FAT * 6) * 250 + "}" * 250), set()),
    # Chains: linear in the analyses, recursion bounded by MAX_DEPTH.
    "10000-chained-assignments": (lambda: _shader("x = y = " * 5000 + "x;"), {"C006"}),
    "5000-chained-assignments": (lambda: _shader("x = y = " * 2500 + "x;"), set()),
    "5000-chained-compound-assignments": (lambda: _shader("x += " * 5000 + "y;"), set()),
    "20000-unary-minus": (lambda: _shader("x = " + "- " * 20000 + "y;"), {"C006"}),
    "20000-not": (lambda: _shader("b = " + "!" * 20000 + "b;"), {"C006"}),
    "10000-ternaries": (lambda: _shader("x = " + "b ? y : " * 10000 + "y;"), {"C006"}),
    "5000-ternaries": (lambda: _shader("x = " + "b ? y : " * 5000 + "y;"), set()),
    "20000-term-sum": (lambda: _shader("x = " + "x + " * 20000 + "x;"), {"C006"}),
    "5000-term-sum-in-a-call": (lambda: _shader("x = pow(y" + " * y" * 5000 + ", 2.0);"), set()),
    "5000-else-ifs-100KB": (
        lambda: _shader("if (x < 0.0) x = 1.0;\n" + "else if (x < 1.0) x = 2.0;\n" * 5000),
        set(),
    ),
    "8000-else-ifs": (
        lambda: _shader("if (x < 0.0) x = 1.0;\n" + "else if (x < 1.0) x = 2.0;\n" * 8000),
        {"C006"},
    ),
    "5000-prefix-increments": (lambda: _shader("x = " + "++" * 5000 + "y;"), set()),
    "5000-swizzles": (lambda: _shader("x = y" + ".x" * 5000 + ";"), set()),
    # Width: many statements, functions, arguments, declarations (~100 KB each).
    "8000-statements": (lambda: _shader("x += y * 2.0;\n" * 8000), set()),
    "3000-functions": (
        lambda: (
            "float f0(float a) { return a; }\n"
            + "".join(
                f"float f{i}(float a) {{ return f{i - 1}(a) * 2.0; }}\n" for i in range(1, 3000)
            )
            + _shader("x = f2999(y);")
        ),
        set(),
    ),
    "10000-arguments": (
        lambda: (
            "float f("
            + ", ".join(f"float a{i}" for i in range(10000))
            + ") { return a0; }\n"
            + _shader("x = f(" + ", ".join(["y"] * 10000) + ");")
        ),
        set(),
    ),
    "5000-declarations": (
        lambda: _shader("".join(f"float v{i} = v{max(i - 1, 0)} + y;\n" for i in range(5000))),
        set(),
    ),
    # Macros: shared hide sets, bounded expansion (C004 names the macro).
    "1000-doubling-defines": (lambda: _defines(1000, "{p}+{p}", "x = {top};"), {"C004"}),
    "1000-juxtaposed-defines": (lambda: _defines(1000, "{p} {p}", "x = {top};"), {"C004"}),
    "3000-nested-defines": (lambda: _defines(3000, "({p}+1)", "x = {top};"), {"C004"}),
    "200-nested-defines": (lambda: _defines(200, "({p}+1)", "x = {top};"), set()),
    "30-doubling-defines": (lambda: _defines(31, "{p}+{p}", "x = {top};"), {"C004"}),
}


def _lint_bounded(path: Path, *flags: str) -> tuple[subprocess.CompletedProcess[str], float]:
    """`glint lint` on `path` in a process under MEMORY_BYTES, killed after SECONDS."""
    import resource

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))

    start = time.monotonic()
    run = subprocess.run(
        [str(GLINT), "lint", "--no-cache", *flags, str(path)],
        capture_output=True,
        text=True,
        errors="replace",
        timeout=SECONDS,
        preexec_fn=limit,
        cwd=path.parent,
    )
    return run, time.monotonic() - start


def _assert_clean_exit(run: subprocess.CompletedProcess[str]) -> None:
    for bad in ("Traceback", "internal error", "MemoryError", "RecursionError"):
        assert bad not in run.stderr, run.stderr[-3000:]
    assert run.returncode in (0, 1), (run.returncode, run.stderr[-3000:])


@needs_rlimit
@pytest.mark.parametrize("name", list(CASES))
def test_generated_input_is_linted_within_bounds(name: str, tmp_path: Path) -> None:
    make, expected = CASES[name]
    path = tmp_path / f"{name}.glsl"
    path.write_text(make(), encoding="utf-8")
    try:
        run, seconds = _lint_bounded(path, "--no-glslang", "--select", "ALL", "--format", "json")
    except subprocess.TimeoutExpired:
        pytest.fail(f"{name}: not linted within {SECONDS:.0f} s")
    _assert_clean_exit(run)
    codes = {f["code"] for f in json.loads(run.stdout)}
    if expected:
        assert codes & expected, (name, codes)
    else:  # analysed, not given up on
        assert not codes & {"C004", "C006"}, (name, codes)
    assert seconds < SECONDS


@pytest.mark.parametrize(
    ("body", "statements", "loops"),
    [
        ("x = 1.0;", 0, 0),
        ("for (;;) for (;;) for (;;) x = 1.0;", 3, 3),
        ("for (;;) { for (;;) { for (;;) { x = 1.0; } } }", 3, 3),  # braces are no extra level
        ("if (b) while (b) { { x = 1.0; } }", 3, 1),  # a bare block is one
        ("if (b) x = 1.0;" + " else if (b) x = 2.0;" * 50 + " else x = 3.0;", 1, 0),  # a chain
        ("if (b) x = 1.0; else { if (b) x = 2.0; }", 2, 0),
        ("do { switch (1) { case 1: if (b) x = 1.0; } } while (b);", 3, 1),
    ],
)
def test_nesting_counts_statements_in_statements(body: str, statements: int, loops: int) -> None:
    from glint.compiler.glsl import parse, preprocess
    from glint.lint.nesting import tree_nesting

    nesting = tree_nesting(parse(preprocess(_shader(body)).text))
    assert (nesting.statements, nesting.loops) == (statements, loops)


def test_the_messages_say_what_is_too_deep() -> None:
    def message(text: str) -> str:
        findings = glint.lint_shader(text, select="C004,C006", glslang=False)
        assert len(findings) == 1, findings
        return findings[0].message

    deep_loops = CASES["65-nested-loops"][0]()
    assert "(loops nested 65 deep; glint follows 64)" in message(deep_loops)
    assert "(2000 levels; glint follows 256)" in message(CASES["2000-nested-for"][0]())
    assert "glint follows 5,500)" in message(CASES["20000-not"][0]())
    defines = message(CASES["1000-doubling-defines"][0]())
    assert "expanding 'A999'" in defines


def test_valid_code_at_the_limits_is_analysed_alike_everywhere() -> None:
    # Just within each limit: analysed, with the findings of the rules (here: none, no C006).
    at_limit = [
        _shader("for (int i = 0; i < 2; i++) {" * 64 + "x += 1.0;" + "}" * 64),
        _shader("if (b) " * 250 + "x += 1.0;"),
        _shader("{" * 250 + "x += 1.0;" + "}" * 250),
        _shader("x = " + "- " * 5400 + "y;"),
    ]
    for text in at_limit:
        codes = {f.code for f in glint.lint_shader(text, select="ALL", glslang=False)}
        assert "C006" not in codes, codes


# --- text outside ASCII, where glslang sees it ---------------------------------------------

NON_ASCII = _shader("    vec4 c = vec4(1.0) × 0.5;\n    x = c.x;")
WITH_A_FINDING = _shader("    x = pow(y, 2.0) + iGlobalTime;")  # P004: iGlobalTime
DOUBLING_FOR_GLSLANG = _defines(41, "{p}+{p}", "x = {top};")  # 2^40 tokens for glslang


@needs_glslang
def test_non_ascii_text_is_a_finding_of_its_own_file(tmp_path: Path) -> None:
    (tmp_path / "a_times.glsl").write_text(NON_ASCII, encoding="utf-8")
    (tmp_path / "b_other.glsl").write_text(WITH_A_FINDING, encoding="utf-8")
    run = subprocess.run(
        [str(GLINT), "lint", "--no-cache", "--format", "concise", str(tmp_path)],
        capture_output=True, text=True, timeout=120, cwd=tmp_path,
    )  # fmt: skip
    _assert_clean_exit(run)
    assert run.returncode == 1
    line = NON_ASCII.splitlines()[4]
    assert f"a_times.glsl:5:{line.index('×') + 1}: C001 glslang: '×'" in run.stdout, run.stdout
    assert re.search(r"b_other\.glsl:5:\d+: P004 ", run.stdout), run.stdout


@needs_glslang
def test_validate_reports_non_ascii_text(tmp_path: Path) -> None:
    path = tmp_path / "times.glsl"
    path.write_text(NON_ASCII, encoding="utf-8")
    run = subprocess.run(
        [str(GLINT), "validate", str(path)], capture_output=True, text=True, timeout=120
    )
    _assert_clean_exit(run)
    assert run.returncode == 1 and "'×'" in run.stdout, (run.stdout, run.stderr)


@needs_glslang
def test_the_api_reports_non_ascii_text() -> None:
    [finding] = glint.lint_shader(NON_ASCII, select="C001,C003")
    assert (finding.code, finding.line) == ("C001", 5) and "'×'" in finding.message


@needs_glslang
@needs_rlimit
def test_glslang_running_away_is_a_finding_and_the_others_are_linted(tmp_path: Path) -> None:
    (tmp_path / "a_bomb.glsl").write_text(DOUBLING_FOR_GLSLANG, encoding="utf-8")
    (tmp_path / "b_other.glsl").write_text(WITH_A_FINDING, encoding="utf-8")
    try:
        run, _ = _lint_bounded(tmp_path, "--format", "concise")
    except subprocess.TimeoutExpired:
        pytest.fail(f"not linted within {SECONDS:.0f} s")
    _assert_clean_exit(run)
    assert run.returncode == 1
    assert "a_bomb.glsl:1:1: C001 glslang: glslangValidator ran out of memory" in run.stdout
    assert re.search(r"a_bomb\.glsl:\d+:\d+: C004 .*expanding 'A40'", run.stdout), run.stdout
    assert re.search(r"b_other\.glsl:5:\d+: P004 ", run.stdout), run.stdout


# --- fuzzing: any text, any bytes, no exception but GlintError, well-formed findings ---------

FUZZ = settings(
    max_examples=120,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
REAL = sorted(
    p
    for kind in ("valid", "lint", "lint_mistakes")
    for p in (ROOT / "tests" / "corpus" / kind).glob("*.glsl")
)
CODES = set(all_rules()) | {UNUSED_SUPPRESSION}

# A small grammar of GLSL-ish pieces: valid and invalid sequences of real tokens, so the
# input gets past the lexer into the parser, the preprocessor and the analyses.
_NAMES = st.sampled_from(["x", "y", "b", "fragColor", "fragCoord", "iTime", "A", "F", "é"])
_LITERALS = st.sampled_from(["0", "1", "2.0", "0.5", "1e9", "0x1F", "true", ".5f", "1u"])
_OPERATORS = st.sampled_from(["+", "-", "*", "/", "<", ">=", "==", "&&", "||", "^^", "%", "&"])


def _expressions() -> st.SearchStrategy[str]:
    leaves = st.one_of(_NAMES, _LITERALS)
    return st.recursive(
        leaves,
        lambda inner: st.one_of(
            st.tuples(inner, _OPERATORS, inner).map(" ".join),
            st.tuples(st.sampled_from(["-", "!", "++", "--", "~"]), inner).map("".join),
            inner.map(lambda e: f"({e})"),
            st.tuples(inner, inner, inner).map(lambda t: f"{t[0]} ? {t[1]} : {t[2]}"),
            st.tuples(_NAMES, inner).map(lambda t: f"{t[0]} = {t[1]}"),
            st.tuples(
                st.sampled_from(["sin", "pow", "normalize", "vec3", "F", "max"]),
                st.lists(inner, max_size=3),
            ).map(lambda t: f"{t[0]}({', '.join(t[1])})"),
            inner.map(lambda e: f"{e}.xyz"),
            inner.map(lambda e: f"{e}[1]"),
        ),
        max_leaves=12,
    )


def _statements() -> st.SearchStrategy[str]:
    expression = _expressions()
    simple = st.one_of(
        expression.map(lambda e: f"{e};"),
        st.tuples(st.sampled_from(["float", "vec3", "int", "bool"]), _NAMES, expression).map(
            lambda t: f"{t[0]} {t[1]} = {t[2]};"
        ),
        st.sampled_from(["return;", "break;", "continue;", "discard;", ";", "}", "{"]),
    )
    return st.recursive(
        simple,
        lambda inner: st.one_of(
            st.tuples(expression, inner).map(lambda t: f"if ({t[0]}) {t[1]}"),
            st.tuples(expression, inner, inner).map(lambda t: f"if ({t[0]}) {t[1]} else {t[2]}"),
            st.tuples(expression, inner).map(lambda t: f"while ({t[0]}) {t[1]}"),
            inner.map(lambda s: f"for (int i = 0; i < 4; i++) {s}"),
            st.lists(inner, max_size=4).map(lambda s: "{ " + " ".join(s) + " }"),
        ),
        max_leaves=10,
    )


@st.composite
def glsl_ish(draw: st.DrawFn) -> str:
    """A shader from the grammar, with directives, and characters of any kind put in."""
    body = "\n".join(draw(st.lists(_statements(), max_size=8)))
    directives = draw(st.lists(st.sampled_from([
        "#define A x * x", "#define F(a) (a + a)", "#define A A + A", "#if 1", "#endif",
        "#ifdef A", "#else", "#undef A", "#line 9", "#version 300 es", "#pragma x", "#error e",
    ]), max_size=3))  # fmt: skip
    text = "\n".join(directives) + "\n" + _shader(body)
    for _ in range(draw(st.integers(0, 3))):  # any characters, anywhere (× among them)
        at = draw(st.integers(0, len(text)))
        text = text[:at] + draw(st.text(st.characters(), min_size=1, max_size=4)) + text[at:]
    return text


# What is put in: mostly text (so that the file stays UTF-8 and is linted), any bytes too.
_CHUNKS = st.one_of(
    st.text(st.characters(), min_size=1, max_size=4).map(lambda t: t.encode("utf-8", "replace")),
    st.sampled_from([b"{", b"}", b"(", b")", b";", b"#define A ", b"\n", b"/*", b"for(;;)", b"\\"]),
    st.binary(min_size=1, max_size=8),
)


@st.composite
def mutated_bytes(draw: st.DrawFn) -> bytes:
    """A real shader's bytes with bytes inserted, deleted, overwritten or duplicated."""
    data = bytearray(draw(st.sampled_from(REAL)).read_bytes())
    for _ in range(draw(st.integers(1, 6))):
        at = draw(st.integers(0, len(data)))
        kind = draw(st.sampled_from(["insert", "delete", "overwrite", "duplicate"]))
        chunk = draw(_CHUNKS)
        if kind == "insert":
            data[at:at] = chunk
        elif kind == "delete":
            del data[at : at + len(chunk)]
        elif kind == "overwrite":
            data[at : at + len(chunk)] = chunk
        else:
            data[at:at] = data[at : at + draw(st.integers(1, 200))]
    return bytes(data)


def _check(findings: list[Finding], lines: int) -> None:
    for f in findings:
        assert isinstance(f, Finding) and f.code in CODES, f
        assert 1 <= f.line <= lines + 1 and f.column >= 1, f
        assert (f.end_line, f.end_column) >= (f.line, f.column), f
        assert f.severity in ("error", "warning", "info") and f.message, f


@FUZZ
@given(glsl_ish(), st.booleans())
def test_fuzzed_glsl_through_the_api(text: str, with_glslang: bool) -> None:
    try:
        findings = glint.lint_shader(text, select="ALL", glslang=with_glslang and HAS_GLSLANG)
    except GlintError:
        return
    _check(findings, text.count("\n") + 1)


@FUZZ
@given(mutated_bytes())
def test_fuzzed_bytes_through_the_runner(data: bytes) -> None:
    options = Options(select=["ALL"], glslang=HAS_GLSLANG)
    try:
        result = lint_bytes(data, "fuzz.glsl", options, fix=True, unsafe_fixes=True)
    except GlintError:
        return
    _check(result.findings, data.count(b"\n") + 1)
