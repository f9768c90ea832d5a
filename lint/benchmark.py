"""How fast `glint lint` is next to glslangValidator, on the same shader files, in one run.

    python -m glint.lint.benchmark [PATHS...] [--repeat N]

Three timings, each the median of N passes over every file after one warm-up pass:

- glint, all rules, glslang off: glint's own analysis (preprocess, parse, every rule), in
  process, with the rules loaded once;
- glint, all rules with glslang on: the above plus one glslangValidator process per file, what
  a plain `glint lint` does;
- glslangValidator alone, one process per file, wrapped exactly as `glint lint` wraps it
  (`glint.compiler.glslang.validate`).

The default files are the repository's shader corpora (tests/corpus/lint, tests/corpus/valid)
and the composed example scene (site/docs/examples), all of which glslang accepts.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

from glint.compiler.glslang import validate

from .options import Options
from .rules import all_rules
from .runner import lint_text

EXTENSIONS = (".glsl", ".frag", ".fs")
_ROOT = Path(__file__).resolve().parents[1]
# The shader corpora and the composed example scene (catalog snippets put together).
DEFAULT_PATHS = [
    _ROOT / "tests" / "corpus" / "lint",
    _ROOT / "tests" / "corpus" / "valid",
    _ROOT / "site" / "docs" / "examples",
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


def median_time(work: Callable[[], object], repeat: int) -> float:
    """Median wall time of `work` over `repeat` runs, after one untimed warm-up run (which
    builds the parser, imports the rules and fills the OS caches)."""
    work()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def run(files: list[Path], repeat: int = 3, out: object = None) -> dict[str, float]:
    """Time the three ways over `files` and print the table; return the medians (seconds)."""
    stream = out if out is not None else sys.stdout
    sources = [(p.read_text(encoding="utf-8", errors="replace"), str(p)) for p in files]
    lines = sum(text.count("\n") + 1 for text, _ in sources)
    all_rules()  # import every rule module before timing
    has_glslang = shutil.which("glslangValidator") is not None
    own = Options(glslang=False)
    full = Options(glslang=True)
    findings = 0

    def glint_only() -> None:
        nonlocal findings
        findings = sum(len(lint_text(text, name, own).findings) for text, name in sources)

    def glint_full() -> None:
        for text, name in sources:
            lint_text(text, name, full)

    def glslang_only() -> None:
        for text, name in sources:
            validate(text, name)

    timings = {"glint": median_time(glint_only, repeat)}
    if has_glslang:
        timings["glint+glslang"] = median_time(glint_full, repeat)
        timings["glslang"] = median_time(glslang_only, repeat)

    n = max(len(files), 1)
    print(
        f"glint lint benchmark: {len(files)} files, {lines:,} lines, {len(all_rules())} rules, "
        f"median of {repeat} run{'s' if repeat != 1 else ''} after 1 warm-up",
        file=stream,
    )
    print(f"{'':42} {'total':>9} {'per file':>10} {'vs glslang':>11}", file=stream)
    rows = [
        ("glint lint, all rules (glslang off)", "glint"),
        ("glint lint, all rules + glslang", "glint+glslang"),
        ("glslangValidator, one process per file", "glslang"),
    ]
    base = timings.get("glslang")
    for label, key in rows:
        if key not in timings:
            continue
        seconds = timings[key]
        ratio = f"{seconds / base:.2f}x" if base else "n/a"
        print(f"{label:42} {seconds:8.3f}s {1000 * seconds / n:8.1f}ms {ratio:>11}", file=stream)
    print(f"glint's own findings on these files: {findings}", file=stream)
    if base:
        ratio = timings["glint"] / base
        verdict = "faster" if ratio < 1 else "slower"
        speed = 1 / ratio if ratio < 1 else ratio
        print(
            f"ratio glint/glslang: {ratio:.2f} (all rules, glslang off: {speed:.1f}x {verdict} "
            f"than glslangValidator); with glslang on: {timings['glint+glslang'] / base:.2f}",
            file=stream,
        )
    else:
        print("ratio glint/glslang: n/a (glslangValidator not installed)", file=stream)
    return timings


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m glint.lint.benchmark",
        description="Time glint lint (all rules) against glslangValidator on the same files.",
    )
    parser.add_argument("paths", nargs="*", type=Path, help="shader files or directories")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per measure (3)")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    files = shader_files(args.paths or [p for p in DEFAULT_PATHS if p.is_dir()])
    if not files:
        parser.error("no shader files to time; give PATHS")
    run(files, args.repeat)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
