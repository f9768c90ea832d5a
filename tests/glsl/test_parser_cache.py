"""The parser's tables are cached between processes in the user's cache folder: a later process
loads them instead of building them, a damaged file is built anew, an unwritable folder only
costs the build."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

_PROBE = """
import time
import glint.compiler.glsl.parser as P
start = time.perf_counter()
P.glsl_parser()
took = time.perf_counter() - start
tree = P.parse("void main() { float x = a - -1.0; }")
print(tree.data, P._fast_parser() is not None, round(took, 4))
"""


def _run(cache: Path) -> list[str]:
    env = {**os.environ, "XDG_CACHE_HOME": str(cache)}
    done = subprocess.run([sys.executable, "-c", _PROBE], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout.split()


def test_a_second_process_loads_the_cached_tables(tmp_path: Path) -> None:
    first = _run(tmp_path)
    files = list((tmp_path / "glint").glob("glsl-parser-*.pickle"))
    assert len(files) == 1 and files[0].stat().st_mode & 0o077 == 0  # private to the user
    second = _run(tmp_path)
    assert first[:2] == second[:2] == ["start", "True"]
    assert float(second[2]) < float(first[2]) / 3  # loaded, not built


def test_a_damaged_cache_is_built_anew(tmp_path: Path) -> None:
    _run(tmp_path)
    (cached,) = (tmp_path / "glint").glob("glsl-parser-*.pickle")
    cached.write_bytes(b"not a pickle")
    assert _run(tmp_path)[:2] == ["start", "True"]
    assert cached.read_bytes() != b"not a pickle"  # built, then cached again


def test_an_unwritable_cache_folder_costs_only_the_build(tmp_path: Path) -> None:
    blocked = tmp_path / "file-not-folder"
    blocked.write_text("x")  # the cache 'folder' is a file: nothing can be written under it
    assert _run(blocked)[:2] == ["start", "True"]
