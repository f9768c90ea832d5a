"""How fast `glint lint` is next to glslangValidator, on the same shader files, in one run.

    python -m glint.lint.benchmark [PATHS...] [--repeat N] [--jobs N]

Five ways over the same files, each timed as a user runs it (a subprocess, so process start,
imports and the worker processes are counted), the median of N runs:

  (a) glint lint, cold (--no-cache), glslang off: glint's own analysis with the default rules;
  (b) glint lint, cold, glslang on: what a plain `glint lint` does on files it has not seen;
  (c) glslangValidator, one process per file, one file after another, as editors and per-file
      hooks run it: the baseline, 1.00x;
  (d) glslangValidator, every file in one process (it compiles each file separately);
  (e) glint lint, warm: a plain `glint lint` again, its cache filled by a run before.

glslangValidator is given each file wrapped exactly as glint wraps it for the target (ShaderToy:
its uniforms before, a `main` after); the wrapping is done once, outside the timings. The glint
runs use a cache directory of their own, so the user's `.glint_cache` is neither read nor
changed. Goals: (a) and (b) faster than (c), (a) at 0.3x as the moonshot; (e) at most 0.05x.
Peak memory is the largest resident set of each measure's processes (wait4), and of this
process and all its children (getrusage).

The default files are the repository's shader corpora (tests/corpus/lint, tests/corpus/valid)
and the composed example scene (site/docs/examples); give `../shared/corpus/shadertoy` for the
real ShaderToy corpus.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

from glint.compiler.target.glslang import wrap_for_target

from .parallel import available_cores

EXTENSIONS = (".glsl", ".frag", ".fs")
_ROOT = Path(__file__).resolve().parents[1]
# The shader corpora and the composed example scene (catalog snippets put together).
DEFAULT_PATHS = [
    _ROOT / "tests" / "corpus" / "lint",
    _ROOT / "tests" / "corpus" / "valid",
    _ROOT / "site" / "docs" / "examples",
]
# (key, label); (c) is the baseline of every ratio.
ROWS = [
    ("a", "glint lint, cold, glslang off"),
    ("b", "glint lint, cold, glslang on"),
    ("c", "glslangValidator, one process per file"),
    ("d", "glslangValidator, all files in one process"),
    ("e", "glint lint, warm (cache filled)"),
]
BASELINE = "c"
# (key, the ratio to (c) to reach, what it says)
GOALS = [
    ("a", 1.0, "cold lint, glslang off, faster than glslangValidator per file"),
    ("a", 0.3, "moonshot: cold lint, glslang off, at 0.3x"),
    ("b", 1.0, "cold lint with glslang faster than glslangValidator per file"),
    ("e", 0.05, "warm lint at most 0.05x"),
]


def shader_files(paths: list[Path]) -> list[Path]:
    """Files as given; directories searched (recursively) for shader extensions."""
    files: list[Path] = []
    for path in paths:
        if path.is_dir():
            files += sorted(p for p in path.rglob("*") if p.suffix in EXTENSIONS and p.is_file())
        elif path.is_file():
            files.append(path)
        else:
            raise SystemExit(f"benchmark: {path}: no such file or directory")
    return files


@dataclass
class Measure:
    key: str
    label: str
    times: list[float] = field(default_factory=list)
    peak_kib: int = 0  # the largest resident set of the measure's processes

    @property
    def seconds(self) -> float:
        return statistics.median(self.times)


def run_process(args: list[str], ok: tuple[int, ...] = (0,)) -> tuple[float, int, str]:
    """Run a command to its end: (wall seconds, the largest resident set in KiB among it and
    the processes it waited for, its stdout). A status outside `ok` stops the benchmark."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        proc = subprocess.Popen(args, stdout=out, stderr=err)
        # wait4, not Popen.wait: it also gives this process tree's peak memory
        _, status, usage = os.wait4(proc.pid, 0)
        elapsed = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        printed, complaint = out.read(), err.read()
    if proc.returncode not in ok:
        detail = (complaint or printed).decode("utf-8", "replace").strip().splitlines()[-3:]
        raise SystemExit(f"benchmark: {args[0]} exited {proc.returncode}: {' '.join(detail)}")
    return elapsed, usage.ru_maxrss, printed.decode("utf-8", "replace")


def glint_command() -> list[str]:
    """The `glint` command of this Python environment."""
    script = Path(sys.executable).with_name("glint")
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "import sys; from glint.compiler.cli import main; "
            "sys.exit(main())"]  # fmt: skip


def run(
    files: list[Path],
    repeat: int = 3,
    jobs: int | None = None,
    target: str = "shadertoy",
    out: TextIO | None = None,
) -> dict[str, float]:
    """Time the five ways over `files`, print the report, return the medians (seconds)."""
    stream = out if out is not None else sys.stdout
    validator = shutil.which("glslangValidator")
    glint = glint_command()
    names = [str(p) for p in files]
    lines = sum(p.read_bytes().count(b"\n") + 1 for p in files)
    job_flags = ["--jobs", str(jobs)] if jobs is not None else []
    measures = {key: Measure(key, label) for key, label in ROWS}
    findings = {"a": 0, "b": 0}

    with tempfile.TemporaryDirectory(prefix="glint-benchmark-") as work:
        cache = os.path.join(work, "cache")
        wrapped = _wrap_all(files, target, Path(work, "wrapped")) if validator else []

        def glint_lint(*flags: str) -> Callable[[], tuple[float, int, str]]:
            args = [*glint, "lint", "--format", "json", "--target", target, *job_flags,
                    "--cache-dir", cache, *flags, *names]  # fmt: skip
            return lambda: run_process(args, ok=(0, 1))

        plan: list[tuple[str, Callable[[], tuple[float, int, str]]]] = []
        if validator:
            # first: the cheapest, and it brings the files and glslang into the OS caches
            plan.append(("d", lambda: run_process([validator, *wrapped], ok=(0, 1, 2))))
            plan.append(("c", lambda: _one_by_one(validator, wrapped)))
        plan.append(("a", glint_lint("--no-cache", "--no-glslang")))
        if validator:
            plan.append(("b", glint_lint("--no-cache")))
            # fill the cache once (untimed), then time plain runs that find it full
            plan.append(("fill", glint_lint()))
            plan.append(("e", glint_lint()))
        for key, work_once in plan:
            for _ in range(1 if key == "fill" else repeat):
                elapsed, peak, printed = work_once()
                if key == "fill":
                    continue
                measures[key].times.append(elapsed)
                measures[key].peak_kib = max(measures[key].peak_kib, peak)
                if key in findings:
                    findings[key] = len(json.loads(printed or "[]"))

    timings = {m.key: m.seconds for m in measures.values() if m.times}
    _report(stream, files, lines, repeat, jobs, measures, timings, findings, validator)
    return timings


def _wrap_all(files: list[Path], target: str, folder: Path) -> list[str]:
    """Each file wrapped as glint wraps it for glslang, as a .frag file (the stage)."""
    folder.mkdir()
    wrapped = []
    for index, path in enumerate(files):
        text = path.read_bytes().decode("utf-8-sig", errors="replace")
        full, _ = wrap_for_target(text, target)
        out = folder / f"{index:05d}_{path.stem}.frag"
        out.write_text(full, encoding="utf-8")
        wrapped.append(str(out))
    return wrapped


def _one_by_one(validator: str, wrapped: list[str]) -> tuple[float, int, str]:
    total, peak = 0.0, 0
    for path in wrapped:
        elapsed, rss, _ = run_process([validator, path], ok=(0, 1, 2))
        total += elapsed
        peak = max(peak, rss)
    return total, peak, ""


def _report(
    stream: TextIO,
    files: list[Path],
    lines: int,
    repeat: int,
    jobs: int | None,
    measures: dict[str, Measure],
    timings: dict[str, float],
    findings: dict[str, int],
    validator: str | None,
) -> None:
    def say(text: str = "") -> None:
        print(text, file=stream)

    workers = jobs if jobs else available_cores()
    say(
        f"glint lint benchmark: {len(files)} files, {lines:,} lines; median of {repeat} "
        f"run{'s' if repeat != 1 else ''}; {available_cores()} cores, glint --jobs {workers}, "
        f"Python {platform.python_version()}"
    )
    base = timings.get(BASELINE)
    say(f"{'':4}{'':46} {'total':>9} {'per file':>10} {'vs (c)':>8} {'peak RSS':>10}")
    n = max(len(files), 1)
    for key, label in ROWS:
        m = measures[key]
        if not m.times:
            say(f"({key}) {label:46} {'n/a (glslangValidator not installed)':>40}")
            continue
        ratio = f"{m.seconds / base:.2f}x" if base else "n/a"
        say(
            f"({key}) {label:46} {m.seconds:8.2f}s {1000 * m.seconds / n:8.1f}ms {ratio:>8} "
            f"{m.peak_kib / 1024:7.0f} MiB"
        )
    say(f"findings: (a) {findings['a']}, (b) {findings['b']}")
    for key, goal, what in GOALS:
        if key not in timings or not base:
            say(f"goal {what}: n/a")
            continue
        ratio = timings[key] / base
        verdict = "met" if ratio <= goal else "not met"
        say(f"goal ({key}) <= {goal:g}x, {what}: {ratio:.2f}x, {verdict}")
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    say(
        f"peak memory (max RSS): this process {own / 1024:.0f} MiB, "
        f"largest child {children / 1024:.0f} MiB"
    )
    if not validator:
        say("glslangValidator not installed: (b)-(e) and the ratios need it")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m glint.lint.benchmark",
        description="Time glint lint (cold, warm, with and without glslang) against "
        "glslangValidator on the same files.",
    )
    parser.add_argument("paths", nargs="*", type=Path, help="shader files or directories")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per measure (3)")
    parser.add_argument(
        "--jobs", type=int, default=None, help="glint's --jobs (default: glint's, one per core)"
    )
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    files = shader_files(args.paths or [p for p in DEFAULT_PATHS if p.is_dir()])
    if not files:
        parser.error("no shader files to time; give PATHS")
    run(files, args.repeat, args.jobs)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
