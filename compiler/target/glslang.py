"""Validate a ShaderToy shader with glslangValidator and report errors where the user wrote them.

The user's code is wrapped exactly as the target wraps it (ShaderToy's prelude and `main`), compiled
by the Khronos reference compiler, and every error line is mapped back through the prelude and the
`// source:` markers to the user's file, or to the snippet the line was copied from.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass

from glint.compiler.errors import EnvironmentProblem, UsageError
from glint.compiler.target import shadertoy, tools
from glint.compiler.target.shadertoy import Tab
from glint.compiler.target.sourcemap import Origin, build_line_map, split_lines
from glint.compiler.target.tools import ToolLimit

TARGETS = shadertoy.TARGETS
TIMEOUT_S = tools.TIMEOUT_S
# validate_many: files per glslangValidator process, and the time each file adds to its limit.
BATCH_FILES = 64
BATCH_FILE_TIMEOUT_S = 2.0
SPIRV_OPT = "/usr/bin/spirv-opt"
MAIN_IMAGE_SIGNATURE = "void mainImage(out vec4 fragColor, in vec2 fragCoord)"

# `ERROR: 0:12: 'foo' : undeclared identifier`; the `0:12: ` part is absent for link errors.
# Some modes print the file name instead of the source-string number 0.
_LINE = re.compile(r"^(ERROR|WARNING): (?:[^\s:]+:(\d+): )?(.*?)\s*$")
_TOKEN = re.compile(r"^'(.*?)' :\s*(.*)$")
# Lines that summarise or follow up real errors and tell the user nothing more.
_NOISE = re.compile(r"compilation errors?\.|No code generated|compilation terminated")
# glslang names the unexpected token in syntax errors by its grammar name.
_GRAMMAR_TOKENS = {
    "SEMICOLON": ";",
    "COMMA": ",",
    "LEFT_BRACE": "{",
    "RIGHT_BRACE": "}",
    "LEFT_PAREN": "(",
    "RIGHT_PAREN": ")",
    "LEFT_BRACKET": "[",
    "RIGHT_BRACKET": "]",
    "DOT": ".",
    "EQUAL": "=",
}
_UNEXPECTED = re.compile(r"unexpected ([A-Z_]+)")


@dataclass
class Diagnostic:
    """One message from the compiler, located in the user's file (1-based line and column)."""

    file: str
    line: int
    column: int
    severity: str  # "error" or "warning"
    message: str

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}: {self.severity}: {self.message}"


def find_validator() -> str:
    """Return the path of glslangValidator, or say how to install it."""
    path = shutil.which("glslangValidator")
    if path is None:
        raise EnvironmentProblem(
            "glslangValidator not found; install it with `apt-get install glslang-tools` "
            "(Debian) or run `make setup`"
        )
    return path


def wrap_for_target(source: str, target: str, tab: Tab | None = None) -> tuple[str, int]:
    """Return the complete fragment shader for `target` (within `tab`: the Common tab in front,
    the channels' types) and how many lines precede the user's first line. A source that
    already opens with `#version` is complete as it is."""
    if target not in TARGETS:
        raise UsageError(f"unknown target {target!r}; expected one of: {', '.join(TARGETS)}")
    if shadertoy.is_complete(source):
        return source, 0
    return shadertoy.wrap_tab(target, source, tab or Tab())


def _run(args: list[str], timeout: float = TIMEOUT_S) -> subprocess.CompletedProcess[str]:
    """The tool's output, decoded; ToolLimit when it runs out of time or memory (tools.py)."""
    return tools.run_tool(args, timeout)


def _compile(
    wrapped: str, workdir: str, extra_args: list[str], stage: str = "frag"
) -> subprocess.CompletedProcess[str]:
    """Compile `wrapped` from a .frag (.vert) file in `workdir` (the suffix tells glslang the
    stage)."""
    validator = find_validator()
    shader = os.path.join(workdir, f"shader.{stage}")
    with open(shader, "w", encoding="utf-8", errors="surrogateescape") as handle:
        handle.write(wrapped)
    return _run([validator, *extra_args, shader])


def _column(line_text: str, token: str, message: str) -> int:
    """glslang reports no column: find the quoted token (or the unexpected one) on the line."""
    if not token:
        unexpected = _UNEXPECTED.search(message)
        token = _GRAMMAR_TOKENS.get(unexpected.group(1), "") if unexpected else ""
    if not token:
        return 1
    if re.fullmatch(r"\w+", token):
        found = re.search(rf"\b{re.escape(token)}\b", line_text)
        return found.start() + 1 if found else 1
    index = line_text.find(token)
    return index + 1 if index >= 0 else 1


def _line_map(text: str, filename: str, markers: bool) -> list[Origin]:
    """Each line's origin: through the `// source:` markers, or (without) the line itself."""
    if markers:
        return build_line_map(text, filename)
    return [Origin(filename, index + 1) for index in range(len(split_lines(text)))]


def _definition(
    source: str, filename: str, name: str, markers: bool = True
) -> tuple[Origin, int] | None:
    """Where `name(` first appears in the user's code: its origin and 1-based column."""
    origins = _line_map(source, filename, markers)
    for index, line in enumerate(split_lines(source)):
        found = re.search(rf"\b{name}\s*\(", line)
        if found:
            return Origin(origins[index].file, origins[index].line), found.start() + 1
    return None


def _epilogue_diagnostic(
    source: str, filename: str, token: str, message: str, severity: str, markers: bool = True
) -> Diagnostic:
    """Explain an error in the `main` that the target appends: the user's entry point is wrong.

    It is reported at the user's definition when there is one, else at the last line.
    """
    if token == "mainImage":
        found = _definition(source, filename, "mainImage", markers)
        what = "has the wrong signature" if found else "is not defined"
        text = f"mainImage {what}: ShaderToy calls `{MAIN_IMAGE_SIGNATURE}`"
    elif token == "main":
        found = _definition(source, filename, "main", markers)
        text = "do not define `main`: ShaderToy defines it and calls `mainImage`"
    else:
        found = None
        text = f"{message} (in the `main` that ShaderToy appends, which calls mainImage)"
    if found:
        origin, column = found
        return Diagnostic(origin.file, origin.line, column, severity, text)
    origins = _line_map(source, filename, markers)
    last = origins[-1] if origins else Origin(filename, 1)
    return Diagnostic(last.file, last.line, 1, severity, text)


def parse_output(
    output: str,
    source: str,
    filename: str,
    prelude_lines: int,
    tab: Tab | None = None,
    markers: bool = True,
) -> list[Diagnostic]:
    """Turn glslangValidator's output on a wrapped `source` into diagnostics on the user's files:
    a line of the Common tab's code (the last lines of the prelude) at `tab.common_file`.
    `markers=False` reports the lines of the file as written, not where `// source:` says."""
    origins = _line_map(source, filename, markers)
    user_lines = split_lines(source)
    common = tab.common if tab is not None and not tab.is_common else ""
    common_lines = split_lines(common)
    common_origins = _line_map(common, tab.common_file if tab else "", markers) if common else []
    diagnostics: list[Diagnostic] = []
    for raw in output.splitlines():
        match = _LINE.match(raw.strip())
        if not match or _NOISE.search(match.group(3)):
            continue
        severity = "error" if match.group(1) == "ERROR" else "warning"
        token_match = _TOKEN.match(match.group(3))
        token, message = token_match.groups() if token_match else ("", match.group(3))
        message = message.strip() or match.group(3)
        user_line = int(match.group(2)) - prelude_lines if match.group(2) else 0
        in_user_code = 1 <= user_line <= len(user_lines)
        token = _whole_character(token, user_lines[user_line - 1] if in_user_code else "")
        if token and token_match:
            message = f"'{token}': {message}"
        if match.group(2) is None:
            # Link-stage errors name no line; the whole file is at fault.
            diagnostics.append(Diagnostic(filename, 1, 1, severity, message))
            continue
        if 1 <= user_line + len(common_lines) <= len(common_lines):  # in the Common tab
            index = user_line + len(common_lines) - 1
            origin = common_origins[index]
            column = _column(common_lines[index], token, message)
            diagnostics.append(Diagnostic(origin.file, origin.line, column, severity, message))
        elif user_line < 1:
            diagnostics.append(Diagnostic(filename, 1, 1, severity, f"in the prelude: {message}"))
        elif user_line > len(origins):
            diagnostics.append(
                _epilogue_diagnostic(source, filename, token, message, severity, markers)
            )
        else:
            origin = origins[user_line - 1]
            column = _column(user_lines[user_line - 1], token, message)
            diagnostics.append(Diagnostic(origin.file, origin.line, column, severity, message))
    return _unique(diagnostics)


def _whole_character(token: str, line_text: str) -> str:
    """glslang names a character outside ASCII by its first byte alone (`×` is the byte 0xc3),
    which reads back as U+FFFD: name the line's first such character instead."""
    if "\ufffd" not in token:
        return token
    found = re.search(r"[^\x00-\x7f]", line_text)
    return found.group() if found else token


def _unique(diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    seen: set[str] = set()
    kept = []
    for diagnostic in diagnostics:
        if str(diagnostic) not in seen:
            seen.add(str(diagnostic))
            kept.append(diagnostic)
    return kept


def validate(
    source: str,
    filename: str = "<input>",
    target: str = "shadertoy",
    tab: Tab | None = None,
    markers: bool = True,
) -> list[Diagnostic]:
    """Compile `source` as `target` would (within `tab`: after the Common tab's code, with its
    channels' types) and return its diagnostics (empty when it is clean). glslang running out
    of time or memory on it is one error diagnostic, at its first line. `markers=False`: at
    the lines of the file as written (lint), not where its `// source:` markers point."""
    wrapped, prelude_lines = wrap_for_target(source, target, tab)
    with tempfile.TemporaryDirectory(prefix="glint-glslang-") as workdir:
        try:
            result = _compile(wrapped, workdir, [])
        except ToolLimit as exc:
            return [Diagnostic(filename, 1, 1, "error", exc.message)]
    output = result.stdout + result.stderr
    return _diagnostics(output, result.returncode, source, filename, prelude_lines, tab, markers)


def validate_stage(source: str, filename: str, stage: str) -> list[Diagnostic]:
    """Compile a complete shader (it opens with #version) as `stage` ("vert" or "frag") and
    return its diagnostics, at the snippet file and line its markers name."""
    with tempfile.TemporaryDirectory(prefix="glint-glslang-") as workdir:
        try:
            result = _compile(source, workdir, [], stage)
        except ToolLimit as exc:
            return [Diagnostic(filename, 1, 1, "error", exc.message)]
    output = result.stdout + result.stderr
    return _diagnostics(output, result.returncode, source, filename, 0)


def _diagnostics(
    output: str,
    returncode: int,
    source: str,
    filename: str,
    prelude_lines: int,
    tab: Tab | None = None,
    markers: bool = True,
) -> list[Diagnostic]:
    diagnostics = parse_output(output, source, filename, prelude_lines, tab, markers)
    if returncode != 0 and not any(d.severity == "error" for d in diagnostics):
        # A failure we could not parse must not pass silently.
        if returncode < 0:
            crashed = f"crashed ({tools.signal_name(returncode)}) on this file"
            detail = f"{crashed}: {output.strip()}" if output.strip() else crashed
        else:
            detail = output.strip() or f"exit status {returncode}"
        diagnostics.append(Diagnostic(filename, 1, 1, "error", f"glslangValidator: {detail}"))
    return diagnostics


def validate_many(
    sources: Sequence[tuple[str, str]],
    target: str = "shadertoy",
    tabs: Sequence[Tab] | None = None,
    markers: bool = True,
) -> list[list[Diagnostic]]:
    """`validate` for many (source, filename) pairs with one glslangValidator process per
    BATCH_FILES files instead of one per file; the diagnostics of each, in the given order.

    Each source is wrapped as `validate` wraps it and written to a file of its own; glslang
    compiles the files given on one command line separately (no linking between them) and
    prints each file's name on a line of its own before that file's messages. The output is
    cut at those names and each part parsed against its own source, with the same line
    mapping as `validate`. Where the output cannot be cut that way (a crash, a message on
    stderr, a name missing), the batch is validated again one file at a time: the results are
    always those of `validate`, only faster. `tabs` gives each source's `tab`."""
    every = list(tabs) if tabs is not None else [Tab()] * len(sources)
    results: list[list[Diagnostic]] = []
    for start in range(0, len(sources), BATCH_FILES):
        batch = [
            (source, name, tab)
            for (source, name), tab in zip(
                sources[start : start + BATCH_FILES],
                every[start : start + BATCH_FILES],
                strict=True,
            )
        ]
        results += _validate_batch(batch, target, markers) or [
            validate(s, f, target, tab, markers) for s, f, tab in batch
        ]
    return results


def _validate_batch(
    batch: Sequence[tuple[str, str, Tab]], target: str, markers: bool
) -> list[list[Diagnostic]] | None:
    """One glslangValidator process for the batch, or None when its output cannot be split."""
    wrapped = [wrap_for_target(source, target, tab) for source, _, tab in batch]
    validator = find_validator()
    with tempfile.TemporaryDirectory(prefix="glint-glslang-") as workdir:
        paths = []
        for index, (text, _) in enumerate(wrapped):
            path = os.path.join(workdir, f"{index:05d}.frag")  # .frag: the fragment stage
            with open(path, "w", encoding="utf-8", errors="surrogateescape") as handle:
                handle.write(text)
            paths.append(path)
        timeout = TIMEOUT_S + BATCH_FILE_TIMEOUT_S * len(paths)
        try:
            result = _run([validator, *paths], timeout)
        except ToolLimit:
            return None  # one file ran away: `validate` finds which, alone
    sections = _split_by_file(result.stdout, paths)
    if sections is None or result.stderr.strip() or result.returncode < 0:
        return None
    # glslang's exit status covers the whole batch; a file failed if its part has an ERROR.
    failed = [any(line.startswith("ERROR") for line in part.splitlines()) for part in sections]
    if result.returncode != 0 and not any(failed):
        return None  # it failed, and no file says why: let `validate` find out which
    return [
        _diagnostics(part, result.returncode if bad else 0, source, filename, prelude, tab, markers)
        for (source, filename, tab), (_, prelude), part, bad in zip(
            batch, wrapped, sections, failed, strict=True
        )
    ]


def _split_by_file(output: str, paths: list[str]) -> list[str] | None:
    """glslang's output cut into each file's part: every file's name comes on a line of its
    own, in the order given, before its messages. None if the output is not like that."""
    parts: list[list[str]] = []
    for line in output.splitlines():
        if len(parts) < len(paths) and line.strip() == paths[len(parts)]:
            parts.append([])
        elif parts:
            parts[-1].append(line)
        elif line.strip():
            return None  # a message before the first file's name
    if len(parts) != len(paths):
        return None
    return ["\n".join(part) for part in parts]


def spirv_instruction_count(source: str, target: str = "shadertoy") -> int | None:
    """Static cost: SPIR-V instructions after `spirv-opt -O`, or None if it does not compile.

    Deterministic, so CI can compare it; without spirv-opt the unoptimised count is returned.
    """
    wrapped, _ = wrap_for_target(source, target)
    # SPIR-V needs ES 3.10; ShaderToy code is valid there, and the count is what matters.
    wrapped = wrapped.replace("#version 300 es", "#version 310 es", 1)
    with tempfile.TemporaryDirectory(prefix="glint-glslang-") as workdir:
        spirv = os.path.join(workdir, "shader.spv")
        # OpenGL-flavoured SPIR-V (-G); loose uniforms need locations and bindings assigned.
        flags = ["-G", "--auto-map-bindings", "--auto-map-locations", "-o", spirv]
        result = _compile(wrapped, workdir, flags)
        if result.returncode != 0 or not os.path.exists(spirv):
            return None
        if os.path.exists(SPIRV_OPT):
            optimised = os.path.join(workdir, "shader.opt.spv")
            if _run([SPIRV_OPT, "-O", spirv, "-o", optimised]).returncode == 0:
                spirv = optimised
        disassembler = shutil.which("spirv-dis")
        if disassembler is None:
            return None
        listing = _run([disassembler, "--no-header", spirv]).stdout
        return sum(1 for line in listing.splitlines() if line.strip())
