"""One `glint bench` run: the variants, then the scenes and tiers with the template baseline,
side by side on one machine, with a progress bar per part."""

from __future__ import annotations

import os
import platform
from collections.abc import Callable, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass

from glint.compiler.bench.report import BenchResult
from glint.compiler.bench.scenes import (
    DEFAULT_SIZE,
    TEMPLATE_SCENE,
    TIERS,
    bench_goals,
    example_scenes,
    measure_scenes,
)
from glint.compiler.bench.variants import is_cpu_renderer, measurable_ids, measure_variants
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.errors import UsageError

# A progress bar: given a label and a total, a context manager whose value is called once per
# finished item (the CLI passes tqdm; tests pass nothing).
ProgressFactory = Callable[[str, int], AbstractContextManager[Callable[[str], None]]]


@dataclass
class BenchOptions:
    slots: Sequence[str] | None = None  # None: every slot with measurable variants
    scenes: Sequence[str] | None = None  # example names or .toml paths; None: every example
    size: tuple[int, int] = DEFAULT_SIZE
    repeats: int = 7
    variants: bool = True
    tiers: bool = True


def variant_ids(slots: Sequence[str] | None) -> list[str]:
    ids = measurable_ids(load_catalog())
    if slots is None:
        return ids
    known = sorted({i.split(".", 1)[0] for i in ids}, key=list(SLOTS).index)
    unknown = [s for s in slots if s not in known]
    if unknown:
        raise UsageError(f"--slots: unknown slot {unknown[0]!r}; slots: {', '.join(known)}")
    return [i for i in ids if i.split(".", 1)[0] in slots]


def run_bench(options: BenchOptions, progress: ProgressFactory | None = None) -> BenchResult:
    renderer = ""
    result = BenchResult(machine={})
    if options.variants:
        ids = variant_ids(options.slots)
        with _bar(progress, "variants", len(ids)) as tick:
            result.variants, renderer = measure_variants(
                ids=ids, repeats=options.repeats, progress=tick
            )
    if options.tiers:
        scenes = list(options.scenes) if options.scenes is not None else example_scenes()
        # One row per tier per scene, and the template's on the template's scene.
        total = len(TIERS) * len(scenes) + (TEMPLATE_SCENE in scenes)
        with _bar(progress, "scenes × tiers", total) as tick:
            result.tiers, renderer = measure_scenes(
                scenes, size=options.size, repeats=options.repeats, progress=tick
            )
        result.goals = bench_goals(result.tiers)
    result.machine = machine_info(renderer)
    return result


def machine_info(renderer: str) -> dict[str, object]:
    from glint.compiler.compose.pipeline import glint_version

    return {
        "renderer": renderer,
        "cpu": is_cpu_renderer(renderer),
        "platform": f"{platform.system()} {platform.machine()}, {_cores()} cores",
        "processor": platform.processor() or platform.machine(),
        "glint": glint_version(),
    }


def _cores() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


class _Silent(AbstractContextManager[Callable[[str], None]]):
    def __enter__(self) -> Callable[[str], None]:
        return lambda label: None

    def __exit__(self, *exc: object) -> None:
        return None


def _bar(progress: ProgressFactory | None, label: str, total: int) -> AbstractContextManager:
    return _Silent() if progress is None else progress(label, total)
