"""glslangValidator runs on the ShaderToy-wrapped code and reports at the user's file and line."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys

import pytest

from glint.compiler.errors import EnvironmentProblem, UsageError
from glint.compiler.target import glslang, tools
from glint.compiler.target.glslang import (
    find_validator,
    spirv_instruction_count,
    validate,
    validate_many,
)
from glint.compiler.target.sourcemap import Origin, build_line_map

needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)

VALID = """\
float brightness(vec2 uv) {
    return 0.5 + 0.5 * sin(iTime + uv.x);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = vec4(vec3(brightness(uv)), 1.0) + texture(iChannel0, uv) * iMouse.x;
}
"""


def test_line_map_follows_markers() -> None:
    text = (
        "// header\n"
        "// source: snippets/D/ggx.glsl:12\n"
        "float D_GGX() {\n"
        "    return 1.0;\n"
        "// source: <generated>:1\n"
        "void mainImage() {}\n"
    )
    assert build_line_map(text, "out.glsl") == [
        Origin("out.glsl", 1),
        Origin("out.glsl", 2),
        Origin("snippets/D/ggx.glsl", 12),
        Origin("snippets/D/ggx.glsl", 13),
        Origin("out.glsl", 5),
        Origin("out.glsl", 6),
    ]


def test_marker_must_be_a_whole_line() -> None:
    origins = build_line_map("  // source: a.glsl:3\nx\n", "out.glsl")
    assert origins == [Origin("out.glsl", 1), Origin("out.glsl", 2)]


@needs_glslang
@pytest.mark.parametrize("target", ["shadertoy", "webgl2", "desktop"])
def test_valid_shader_has_no_diagnostics(target: str) -> None:
    assert validate(VALID, "ok.glsl", target) == []


@needs_glslang
@pytest.mark.parametrize("target", ["shadertoy", "desktop"])
def test_error_is_reported_at_the_user_line_and_token(target: str) -> None:
    source = VALID.replace("vec2 uv = fragCoord", "vec2 uv = fragCoordd")
    [diagnostic] = validate(source, "bad.glsl", target)
    assert (diagnostic.file, diagnostic.line, diagnostic.severity) == ("bad.glsl", 6, "error")
    assert diagnostic.column == source.splitlines()[5].index("fragCoordd") + 1
    assert "fragCoordd" in diagnostic.message
    assert str(diagnostic).startswith(f"bad.glsl:6:{diagnostic.column}: error: ")


@needs_glslang
def test_syntax_error_column_points_at_the_unexpected_token() -> None:
    source = "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(1.0)\n}\n"
    [diagnostic] = validate(source, "s.glsl")
    assert (diagnostic.line, diagnostic.column) == (3, 1)
    assert "syntax error" in diagnostic.message


@needs_glslang
def test_error_in_composed_shader_maps_to_the_snippet() -> None:
    composed = (
        "// glint: composed shader\n"
        "// source: snippets/D/ggx.glsl:7\n"
        "float D_GGX(float NoH, float a) {\n"
        "    float a2 = a * a;\n"
        "    return a2 / (NoH * undefinedThing);\n"
        "}\n"
        "// source: <generated>:1\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    fragColor = vec4(D_GGX(0.5, 0.3));\n"
        "}\n"
    )
    [diagnostic] = validate(composed, "scene.glsl")
    assert (diagnostic.file, diagnostic.line) == ("snippets/D/ggx.glsl", 9)
    assert diagnostic.column == composed.splitlines()[4].index("undefinedThing") + 1


@needs_glslang
def test_missing_main_image_is_explained() -> None:
    [diagnostic] = validate("float helper() { return 1.0; }\n", "m.glsl")
    assert (diagnostic.file, diagnostic.line) == ("m.glsl", 1)
    assert "mainImage is not defined" in diagnostic.message
    assert "void mainImage(out vec4 fragColor, in vec2 fragCoord)" in diagnostic.message


@needs_glslang
def test_wrong_main_image_signature_is_explained() -> None:
    [diagnostic] = validate("void mainImage(out vec4 c) {\n    c = vec4(1.0);\n}\n", "m.glsl")
    assert (diagnostic.line, diagnostic.column) == (1, 6)  # at the user's definition
    assert "wrong signature" in diagnostic.message


@needs_glslang
def test_user_main_is_reported_where_it_is_defined() -> None:
    source = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n\nvoid main() {}\n"
    [diagnostic] = validate(source, "m.glsl")
    assert (diagnostic.line, diagnostic.column) == (3, 6)
    assert "do not define `main`" in diagnostic.message


def test_unknown_target_is_a_usage_error() -> None:
    with pytest.raises(UsageError, match="desktop"):
        validate(VALID, target="vulkan")


def test_missing_validator_is_an_environment_problem(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PATH", "")
    with pytest.raises(EnvironmentProblem, match="glslang-tools") as raised:
        find_validator()
    assert raised.value.exit_code == 2
    with pytest.raises(EnvironmentProblem):
        validate(VALID)


@needs_glslang
@pytest.mark.skipif(shutil.which("spirv-dis") is None, reason="spirv-dis is not installed")
def test_spirv_instruction_count_grows_with_code() -> None:
    small = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n"
    count = spirv_instruction_count(VALID)
    assert count is not None and count > spirv_instruction_count(small)  # type: ignore[operator]
    assert spirv_instruction_count("not glsl") is None


# --- validate_many: one glslangValidator process for many files ---------------------------------

# Two files with errors on different lines, a clean one between them and a complete shader
# (#version, not wrapped: no prelude to subtract) whose error is on yet another line.
ERROR_ON_LINE_2 = "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(undefinedA);\n}\n"
ERROR_ON_LINE_5 = (
    "float helper(float x) {\n    return x;\n}\n\n"
    "float other() { return undefinedB; }\n"
    "void mainImage(out vec4 c, in vec2 f) { c = vec4(helper(1.0)); }\n"
)
COMPLETE_ERROR_ON_LINE_4 = (
    "#version 300 es\nprecision highp float;\nout vec4 color;\n"
    "void main() { color = vec4(undefinedC); }\n"
)
Completed = subprocess.CompletedProcess[str]
BATCH = [
    (ERROR_ON_LINE_2, "a.glsl"),
    (VALID, "ok.glsl"),
    (ERROR_ON_LINE_5, "b.glsl"),
    (COMPLETE_ERROR_ON_LINE_4, "c.frag"),
]


@needs_glslang
def test_validate_many_keeps_each_files_diagnostics_on_that_file() -> None:
    results = validate_many(BATCH)
    assert len(results) == len(BATCH)
    a, ok, b, c = results
    assert ok == []
    assert [(d.file, d.line, d.severity) for d in a] == [("a.glsl", 2, "error")]
    assert "undefinedA" in a[0].message
    assert [(d.file, d.line, d.severity) for d in b] == [("b.glsl", 5, "error")]
    assert "undefinedB" in b[0].message
    assert [(d.file, d.line) for d in c] == [("c.frag", 4)]
    assert "undefinedC" in c[0].message
    # exactly what one process per file says, columns and messages included
    assert results == [validate(source, name) for source, name in BATCH]


@needs_glslang
def test_validate_many_runs_one_process_per_batch(monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[int] = []
    real_run = glslang._run

    def counting_run(args: list[str], timeout: float = glslang.TIMEOUT_S) -> Completed:
        calls.append(len(args) - 1)
        return real_run(args, timeout)

    monkeypatch.setattr(glslang, "_run", counting_run)
    monkeypatch.setattr(glslang, "BATCH_FILES", 3)
    sources = BATCH + [(ERROR_ON_LINE_2, "d.glsl")]
    results = validate_many(sources)
    assert calls == [3, 2]  # two processes for five files, not five
    files = [[d.file for d in result] for result in results]
    assert files == [["a.glsl"], [], ["b.glsl"], ["c.frag"], ["d.glsl"]]
    assert results[4][0].line == 2  # d.glsl, alone in the second batch


@needs_glslang
def test_validate_many_falls_back_when_the_output_cannot_be_split(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    real_run = glslang._run

    def mangled(args: list[str], timeout: float = glslang.TIMEOUT_S) -> Completed:
        result = real_run(args, timeout)
        if len(args) > 2:  # the batch: lose the file names, as a crash mid-way would
            result.stdout = "\n".join(
                line for line in result.stdout.splitlines() if not line.endswith(".frag")
            )
        return result

    monkeypatch.setattr(glslang, "_run", mangled)
    assert validate_many(BATCH) == [validate(source, name) for source, name in BATCH]


def test_validate_many_of_nothing_runs_nothing() -> None:
    assert validate_many([]) == []


def test_output_is_split_at_the_file_names_in_order() -> None:
    paths = ["/t/00000.frag", "/t/00001.frag"]
    output = "/t/00000.frag\nERROR: 0:3: 'x' : bad\n\n/t/00001.frag\nWARNING: 0:1: w\n"
    assert glslang._split_by_file(output, paths) == ["ERROR: 0:3: 'x' : bad\n", "WARNING: 0:1: w"]
    assert glslang._split_by_file("/t/00000.frag\n", paths) is None  # a file is missing
    assert glslang._split_by_file("oops\n" + output, paths) is None  # text before the first
    swapped = "/t/00001.frag\n/t/00000.frag\n"
    assert glslang._split_by_file(swapped, paths) is None  # out of order


# --- what glslang prints is read whatever the bytes; runaways are bounded -----------------------

NON_ASCII = "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(1.0) × 0.5;\n}\n"
# Each macro is the one before twice: glslang expands 2^40 tokens, hundreds of MB a second.
DOUBLING = (
    "#define A0 f.x\n"
    + "".join(f"#define A{i} A{i - 1}+A{i - 1}\n" for i in range(1, 41))
    + "void mainImage(out vec4 c, in vec2 f) { c = vec4(A40); }\n"
)


@needs_glslang
def test_non_ascii_outside_a_comment_is_an_error_at_that_character() -> None:
    # glslang names `×` by its first byte alone, which is not UTF-8 by itself; reading its
    # output as ASCII (or strict UTF-8) raised instead.
    [diagnostic] = validate(NON_ASCII, "x.glsl")
    assert (diagnostic.line, diagnostic.column, diagnostic.severity) == (2, 19, "error")
    assert diagnostic.message.startswith("'×'")
    assert validate_many([(NON_ASCII, "x.glsl"), (VALID, "ok.glsl")]) == [[diagnostic], []]


def test_tool_output_is_decoded_whatever_its_bytes() -> None:
    script = "import sys; sys.stdout.buffer.write(b'caf\\xc3 \\xff\\n'); sys.exit(3)"
    result = tools.run_tool([sys.executable, "-c", script])
    assert (result.returncode, result.stdout) == (3, "caf\ufffd \ufffd\n")


def test_a_tool_past_its_time_limit_is_an_input_error() -> None:
    with pytest.raises(tools.ToolLimit, match=r"ran out of time on this file \(limit 0.5 s\)") as e:
        tools.run_tool([sys.executable, "-c", "import time; time.sleep(30)"], timeout=0.5)
    assert e.value.exit_code == 1 and e.value.what == "time"


@pytest.mark.skipif(os.name != "posix", reason="the memory limit is set with setrlimit")
def test_a_tool_past_its_memory_limit_is_an_input_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(tools, "MEMORY_LIMIT_BYTES", 256 << 20)
    grow = "import sys\ntry:\n    b = bytearray(1 << 30)\nexcept MemoryError:\n" \
        "    sys.stderr.write('std::bad_alloc'); sys.exit(134)\n"  # fmt: skip
    with pytest.raises(tools.ToolLimit, match="ran out of memory on this file") as raised:
        tools.run_tool([sys.executable, "-c", grow])
    assert raised.value.what == "memory"


@needs_glslang
@pytest.mark.skipif(os.name != "posix", reason="the memory limit is set with setrlimit")
def test_glslang_running_away_is_one_diagnostic(monkeypatch: pytest.MonkeyPatch) -> None:
    # A small limit, so the test is quick; the real one (1 GiB) is reached within seconds too.
    monkeypatch.setattr(tools, "MEMORY_LIMIT_BYTES", 256 << 20)
    [diagnostic] = validate(DOUBLING, "bomb.glsl")
    assert (diagnostic.file, diagnostic.line, diagnostic.severity) == ("bomb.glsl", 1, "error")
    assert diagnostic.message == "glslangValidator ran out of memory on this file (limit 0.25 GiB)"
    # In a batch, the other files keep their own diagnostics.
    assert validate_many([(VALID, "ok.glsl"), (DOUBLING, "bomb.glsl")]) == [[], [diagnostic]]


def test_a_tool_reads_back_the_memory_limit_it_runs_under() -> None:
    """run_tool puts the tool it starts under MEMORY_LIMIT_BYTES of address space: what the
    tool itself reads back as its limit, once the limit has landed."""
    shell = shutil.which("sh")
    if shell is None or not hasattr(__import__("resource"), "prlimit"):
        pytest.skip("needs a POSIX shell and Linux's prlimit")
    result = tools.run_tool([shell, "-c", "sleep 0.2; ulimit -v"])
    expected = tools.MEMORY_LIMIT_BYTES // 1024
    own = __import__("resource").getrlimit(__import__("resource").RLIMIT_AS)[0]
    if own != -1:  # glint itself under a lower limit: that one holds
        expected = min(expected, own // 1024)
    assert int(result.stdout) == expected
