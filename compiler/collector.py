"""Python's cycle collector paused around work that allocates a large structure at once (a parse
tree, one file's lint): the collector would walk the growing structure again and again while it
is built, for nothing. Nested pauses are one pause."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def paused(collect_after: bool = False) -> Iterator[None]:
    """The collector off inside; with `collect_after`, the youngest generation collected once
    after, which then holds everything made inside that is no longer reachable."""
    if not gc.isenabled():  # nested, or paused by the caller
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        gc.enable()
        if collect_after:
            gc.collect(0)
