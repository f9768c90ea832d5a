"""Run the Khronos command-line tools (glslangValidator, spirv-opt, spirv-dis, spirv-cross) on
a user's shader with bounds on what they may take, and read what they print.

The tools are fed whatever a user wrote, and some inputs make them run away: a macro that
doubles itself a few dozen times makes glslangValidator allocate hundreds of megabytes a
second until the machine runs out. So each runs with a time limit and a limit on its address
space; a tool stopped by either is reported as `ToolLimit`, an error in the input (exit 1)
that says which limit it ran into, never as a crash of glint.

Their output is read as UTF-8 with undecodable bytes replaced: glslang echoes the user's
tokens, and cuts a multi-byte character in half when it names one (`×` becomes `\\xc3`), so
no output may be trusted to decode.
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess

from glint.compiler.errors import EnvironmentProblem, InputError

if os.name == "posix":
    import resource

TIMEOUT_S = 30.0
# Address space a tool may take. glslangValidator peaks at 23 MB on the largest real shader of
# the corpus (116 KB), at 130 MB on 1 MB of code (glint's limit on a file it lints) and at
# 930 MB on 10 MB; spirv-opt at 140 MB on 1 MB of code's SPIR-V. A gibibyte is several times
# what any real shader needs, and a runaway (a macro that doubles itself, 260 MB a second)
# reaches it within seconds instead of taking the machine's memory; several lint workers may
# each run one.
MEMORY_LIMIT_BYTES = 1 << 30
# What a C++ tool prints when an allocation fails under the limit (it then aborts).
_OUT_OF_MEMORY = ("std::bad_alloc", "out of memory", "Cannot allocate memory")


class ToolLimit(InputError):
    """A tool ran out of time or memory on this input (exit 1: the input is what is wrong)."""

    def __init__(self, tool: str, what: str, limit: str) -> None:
        super().__init__(f"{tool} ran out of {what} on this file (limit {limit})")
        self.tool = tool
        self.what = what  # "time" or "memory"


def run_tool(args: list[str], timeout: float = TIMEOUT_S) -> subprocess.CompletedProcess[str]:
    """Run a tool to completion: its exit status and output, decoded. Raises ToolLimit when it
    runs past `timeout` seconds or out of memory, EnvironmentProblem when it cannot start."""
    tool = os.path.basename(args[0])
    try:
        process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    except OSError as exc:
        raise EnvironmentProblem(f"cannot run {args[0]}: {exc.strerror or exc}") from exc
    with process:
        _limit_memory(process.pid)
        try:
            out, err = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            process.communicate()
            raise ToolLimit(tool, "time", f"{timeout:g} s") from None
    stdout, stderr = decode(out), decode(err)
    if _ran_out_of_memory(process.returncode, stderr):
        raise ToolLimit(tool, "memory", f"{MEMORY_LIMIT_BYTES / 2**30:g} GiB")
    return subprocess.CompletedProcess(args, process.returncode, stdout, stderr)


def decode(data: bytes | None) -> str:
    """A tool's output as text, whatever bytes it printed."""
    return data.decode("utf-8", errors="replace") if data else ""


def signal_name(returncode: int) -> str:
    """`SIGSEGV` for a process killed by signal 11 (return code -11)."""
    try:
        return signal.Signals(-returncode).name
    except ValueError:
        return f"signal {-returncode}"


def _ran_out_of_memory(returncode: int, stderr: str) -> bool:
    # An allocation that fails under the limit throws std::bad_alloc, which these tools do not
    # catch: they abort (SIGABRT) after printing it. A tool that catches it exits non-zero.
    return returncode != 0 and any(text in stderr for text in _OUT_OF_MEMORY)


def _limit_memory(pid: int) -> None:
    """Put the started tool under MEMORY_LIMIT_BYTES of address space (Linux), or under the
    lower limit glint itself runs under (`ulimit -v`), which it inherits anyway.

    The limit is set from outside (prlimit) right after the start rather than in the child
    before exec (preexec_fn): that hook may deadlock in a process with threads (a language
    server, a preview server) and makes every start a full fork. A tool allocates nothing much
    in the microseconds before the limit lands; one that has already exited is left alone."""
    prlimit = getattr(resource, "prlimit", None) if os.name == "posix" else None
    if prlimit is None:
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = MEMORY_LIMIT_BYTES
    for bound in (soft, hard):
        if bound != resource.RLIM_INFINITY:
            limit = min(limit, bound)
    with contextlib.suppress(OSError):  # the tool has exited already
        prlimit(pid, resource.RLIMIT_AS, (limit, hard))
