"""`[tool.glint.lint]` of pyproject.toml: select, ignore, per-file-ignores, target.

The nearest pyproject.toml at or above the current directory is read (like ruff); command-line
flags override it."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from glint.compiler.errors import UsageError
from glint.compiler.target.shadertoy import TARGETS

from .options import Options

KEYS = ("select", "ignore", "per-file-ignores", "target")


def find_pyproject(start: Path) -> Path | None:
    for folder in [start, *start.parents]:
        candidate = folder / "pyproject.toml"
        if candidate.is_file():
            return candidate
    return None


def load_options(start: Path | None = None) -> tuple[Options, Path | None]:
    """Options from the nearest pyproject.toml's [tool.glint.lint], and that file."""
    path = find_pyproject((start or Path.cwd()).resolve())
    if path is None:
        return Options(), None
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise UsageError(f"{path}: cannot read the lint configuration: {exc}") from None
    table = data.get("tool", {}).get("glint", {}).get("lint", {})
    return options_from_table(table, str(path)), path


def options_from_table(table: dict[str, Any], where: str) -> Options:
    unknown = sorted(set(table) - set(KEYS))
    if unknown:
        raise UsageError(
            f"{where}: [tool.glint.lint]: unknown key {unknown[0]!r}; keys: {', '.join(KEYS)}"
        )
    options = Options()
    for key in ("select", "ignore"):
        if key in table:
            setattr(options, key, _codes(table[key], f"{where}: [tool.glint.lint].{key}"))
    if "per-file-ignores" in table:
        pfi = table["per-file-ignores"]
        if not isinstance(pfi, dict):
            raise UsageError(f"{where}: [tool.glint.lint].per-file-ignores must be a table")
        options.per_file_ignores = {
            str(glob): _codes(codes, f"{where}: per-file-ignores.{glob}")
            for glob, codes in pfi.items()
        }
    if "target" in table:
        if table["target"] not in TARGETS:
            raise UsageError(
                f"{where}: [tool.glint.lint].target: unknown value {table['target']!r}; "
                f"expected one of {', '.join(TARGETS)}"
            )
        options.target = table["target"]
    return options


def _codes(value: Any, where: str) -> list[str]:
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise UsageError(f'{where}: expected a list of rule codes, e.g. ["N001", "L"]')
    return [v.strip().upper() for v in value]
