"""Lint many files: over the CPU cores in worker processes, glslangValidator run once per chunk
of files rather than once per file, the results in the order of the files.

A handful of files is linted in this process (starting workers would cost more than it saves).
Otherwise the files are cut into chunks, several per worker so that a slow file does not leave
the other cores idle at the end, and `concurrent.futures.ProcessPoolExecutor` lints the chunks;
`map` gives the results back in the files' order, so the output is the same whatever the number
of workers. On Linux the workers are forked: they start with the rules already imported.

Each chunk validates its files with one glslangValidator process (`validate_many`) before its
rules run; the linter's contexts take those diagnostics (`precomputed_glslang`) instead of
running glslang once per file.
"""

from __future__ import annotations

import math
import multiprocessing
import os
import sys
from collections.abc import Sequence
from concurrent.futures import ProcessPoolExecutor
from typing import TypeVar

from glint.compiler.errors import GlintError
from glint.compiler.target.glslang import Diagnostic, validate_many
from glint.compiler.target.shadertoy import Tab

from .context import GlslangKey, precomputed_glslang
from .options import Options
from .runner import LintResult, decode, lint_bytes

# Fewer files than this per worker are linted in this process.
MIN_FILES_PER_WORKER = 2
CHUNKS_PER_WORKER = 6
MAX_CHUNK = 64  # files per chunk, and so per glslangValidator process

Item = tuple[str, bytes]  # the file's name (as reported) and its bytes
Work = tuple[str, bytes, Tab]  # and the ShaderToy tab it is linted in
T = TypeVar("T")


def available_cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def worker_count(files: int, jobs: int | None = None) -> int:
    """How many worker processes for `files` files: at most `jobs` (default: the cores this
    process may use), with at least MIN_FILES_PER_WORKER files each; 1 means this process."""
    jobs = jobs if jobs and jobs > 0 else available_cores()
    return max(1, min(jobs, files // MIN_FILES_PER_WORKER))


def chunks(items: Sequence[T], workers: int) -> list[list[T]]:
    """Consecutive chunks, CHUNKS_PER_WORKER per worker, at most MAX_CHUNK files each."""
    if not items:
        return []
    size = math.ceil(len(items) / (workers * CHUNKS_PER_WORKER))
    size = max(1, min(size, MAX_CHUNK))
    return [list(items[i : i + size]) for i in range(0, len(items), size)]


def lint_items(
    items: Sequence[Item],
    options: Options,
    fix: bool = False,
    unsafe_fixes: bool = False,
    jobs: int | None = None,
    tabs: Sequence[Tab] | None = None,
) -> list[LintResult]:
    """Lint each (name, bytes) as `runner.lint_bytes` does, in its tab of `tabs` (default:
    `options.tab()`); the results in the same order."""
    every = list(tabs) if tabs is not None else [options.tab()] * len(items)
    triples = [(name, data, tab) for (name, data), tab in zip(items, every, strict=True)]
    workers = worker_count(len(items), jobs)
    if workers <= 1:
        return lint_chunk(triples, options, fix, unsafe_fixes)
    work = chunks(triples, workers)
    with ProcessPoolExecutor(max_workers=workers, mp_context=_context()) as pool:
        parts = pool.map(
            lint_chunk,
            work,
            [options] * len(work),
            [fix] * len(work),
            [unsafe_fixes] * len(work),
        )
        return [result for part in parts for result in part]


def lint_chunk(
    items: list[Work], options: Options, fix: bool = False, unsafe_fixes: bool = False
) -> list[LintResult]:
    """Lint consecutive files in this process, glslang run once for all of them."""
    with precomputed_glslang(_glslang_for(items, options)):
        return [_lint_one(data, name, options, fix, unsafe_fixes, tab) for name, data, tab in items]


def _lint_one(
    data: bytes, name: str, options: Options, fix: bool, unsafe_fixes: bool, tab: Tab
) -> LintResult:
    """One file's result. A bug of glint's own on one file is that file's note, not the end of
    the run: the other files are still linted and reported, and the command exits 2."""
    try:
        return lint_bytes(data, name, options, fix, unsafe_fixes, tab)
    except Exception as exc:
        what = f"{type(exc).__name__}: {exc}"
        note = f"{name}: internal error: {what}; please report it with the file"
        return LintResult(name, [], decode(data, name)[0], notes=[note], failed=True)


def _glslang_for(items: list[Work], options: Options) -> dict[GlslangKey, list[Diagnostic]]:
    """glslang's diagnostics for the files that the glslang rules will ask about, by the key
    `precomputed_glslang` takes; empty when glslang is off or cannot run (each file then runs
    it, or fails, as it would alone)."""
    if not options.glslang:
        return {}
    wanted: list[tuple[str, str]] = []
    tabs: list[Tab] = []
    for name, data, tab in items:
        text, problem = decode(data, name)
        asked = options.enabled("C001", name) or options.enabled("C002", name)
        if text and not problem and asked:
            wanted.append((text, name))
            tabs.append(tab)
    if len(wanted) < 2:
        return {}  # one file: `validate` as usual
    try:
        # at the files' own lines, as `LintContext.glslang` asks for them
        results = validate_many(wanted, options.target, tabs, markers=False)
    except GlintError:
        return {}
    return {
        (name, options.target, text, tab): diagnostics
        for (text, name), tab, diagnostics in zip(wanted, tabs, results, strict=True)
    }


def _context() -> multiprocessing.context.BaseContext | None:
    # Forked workers inherit the imported rules; elsewhere (macOS, Windows) fork is unsafe or
    # missing and the platform's default is used.
    if sys.platform == "linux" and "fork" in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("fork")
    return None
