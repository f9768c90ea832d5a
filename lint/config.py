"""`[tool.glint.lint]` of pyproject.toml: select, ignore, per-file-ignores, target, channels.

The nearest pyproject.toml at or above the current directory is read (like ruff); command-line
flags override it. The whole `[tool.glint]` table is checked before anything runs: a key glint
does not know, a value of the wrong type or an unknown rule code is one usage error (exit 2)
that names the file, the key, the value and what was expected."""

from __future__ import annotations

import datetime
import difflib
import json
import math
import re
import tomllib
from pathlib import Path
from typing import Any

from glint.compiler.errors import UsageError
from glint.compiler.target.shadertoy import CHANNEL_KINDS, TARGETS, bind_channels, channel_binding

from .options import Options, unknown_code

KEYS = ("select", "ignore", "per-file-ignores", "target", "channels")
SECTIONS = ("lint",)  # the tables glint reads under [tool.glint]
CODES = 'a list of rule codes or prefixes, e.g. ["N001", "L"]'


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
    return options_from_table(lint_table(data, str(path)), str(path)), path


def lint_table(data: dict[str, Any], where: str) -> dict[str, Any]:
    """`[tool.glint.lint]` of a parsed pyproject.toml ({} when absent), once `[tool]` and
    `[tool.glint]` are found to be tables and `[tool.glint]` to hold only keys glint knows."""
    tool = data.get("tool", {})
    if not isinstance(tool, dict):
        raise _wrong(where, ("tool",), tool, "a table ([tool])")
    glint = tool.get("glint", {})
    if not isinstance(glint, dict):
        raise _wrong(
            where, ("tool", "glint"), glint, "a table ([tool.glint]) with " + _or(SECTIONS)
        )
    _no_unknown_keys(glint, ("tool", "glint"), SECTIONS, where)
    table = glint.get("lint", {})
    if not isinstance(table, dict):
        keys = ", ".join(KEYS)
        raise _wrong(
            where, ("tool", "glint", "lint"), table, f"a table ([tool.glint.lint]) of {keys}"
        )
    return table


def options_from_table(table: dict[str, Any], where: str) -> Options:
    """Options from a `[tool.glint.lint]` table, every key and value checked."""
    _no_unknown_keys(table, ("tool", "glint", "lint"), KEYS, where)
    options = Options()
    for key in ("select", "ignore"):
        if key in table:
            setattr(options, key, _codes(table[key], ("tool", "glint", "lint", key), where))
    if "per-file-ignores" in table:
        pfi = table["per-file-ignores"]
        at = ("tool", "glint", "lint", "per-file-ignores")
        if not isinstance(pfi, dict):
            raise _wrong(
                where, at, pfi, 'a table of file pattern = rule codes, e.g. "gen/*.glsl" = ["N"]'
            )
        options.per_file_ignores = {
            glob: _codes(codes, (*at, glob), where) for glob, codes in pfi.items()
        }
    if "target" in table:
        target = table["target"]
        if not isinstance(target, str) or target not in TARGETS:
            raise _wrong(where, ("tool", "glint", "lint", "target"), target, _or(TARGETS))
        options.target = target
    if "channels" in table:
        options.channels = _channels(table["channels"], where)
    return options


def _channels(value: Any, where: str) -> tuple[str, ...]:
    """`channels = { 0 = "cube", 2 = "3d" }`: what each iChannelN is bound to."""
    at = ("tool", "glint", "lint", "channels")
    kinds = " or ".join(json.dumps(kind) for kind in CHANNEL_KINDS)
    expected = f'a table of channel number = {kinds}, e.g. {{ 0 = "cube" }}'
    if not isinstance(value, dict):
        raise _wrong(where, at, value, expected)
    bindings: list[tuple[int, str]] = []
    for number, kind in value.items():
        try:
            if not isinstance(kind, str):
                raise ValueError(kind)
            bindings.append(channel_binding(f"{number}={kind}"))
        except ValueError:
            raise _wrong(where, (*at, number), kind, f"{kinds}, for a channel 0 to 3") from None
    return bind_channels(Options().channels, bindings)


def _codes(value: Any, key: tuple[str, ...], where: str) -> list[str]:
    if not isinstance(value, list):
        raise _wrong(where, key, value, CODES)
    if not value and key[-1] == "select":
        raise _wrong(where, key, value, f"{CODES}; an empty list selects no rule")
    for item in value:
        if not isinstance(item, str):
            raise _wrong(where, key, value, f"{CODES}; {_show(item)} is {_kind(item)}")
    unknown = unknown_code(value)
    if unknown is not None:
        what = "an empty rule code" if not unknown.strip() else "unknown rule code or prefix"
        raise _wrong(
            where, key, value, f"{CODES}; {what} {_show(unknown)} (see `glint rule --all`)"
        )
    return [v.strip().upper() for v in value]


def _no_unknown_keys(
    table: dict[str, Any], at: tuple[str, ...], known: tuple[str, ...], where: str
) -> None:
    for key in table:
        if key not in known:
            close = difflib.get_close_matches(key, known, n=1)
            hint = f"; did you mean {json.dumps(close[0])}?" if close else ""
            raise UsageError(
                f"{where}: {_key((*at, key))} = {_show(table[key])}: unknown key "
                f"{json.dumps(key)}; [{_key(at)}] takes {_or(known)}{hint}"
            )


def _wrong(where: str, key: tuple[str, ...], value: Any, expected: str) -> UsageError:
    return UsageError(
        f"{where}: {_key(key)} = {_show(value)} ({_kind(value)}): expected {expected}"
    )


_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(parts: tuple[str, ...]) -> str:
    """A dotted TOML key, each part quoted where TOML needs it."""
    return ".".join(part if _BARE_KEY.match(part) else json.dumps(part) for part in parts)


def _or(choices: tuple[str, ...]) -> str:
    quoted = [json.dumps(choice) for choice in choices]
    return quoted[0] if len(quoted) == 1 else f"one of {', '.join(quoted)}"


def _show(value: Any, limit: int = 80) -> str:
    """The value as TOML writes it, cut short when long."""
    text = _toml(value)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, int | float):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # control characters escaped
    if isinstance(value, list):
        return "[" + ", ".join(_toml(item) for item in value) + "]"
    if isinstance(value, dict):
        items = ", ".join(f"{_key((str(k),))} = {_toml(v)}" for k, v in value.items())
        return "{" + items + "}"
    if isinstance(value, datetime.date | datetime.time):
        return value.isoformat()
    return repr(value)


def _kind(value: Any) -> str:
    """The TOML type of a value, with its article."""
    kinds = ((bool, "a boolean"), (int, "an integer"), (float, "a float"), (str, "a string"),
             (list, "an array"), (dict, "a table"), (datetime.datetime, "a date-time"),
             (datetime.date, "a date"), (datetime.time, "a time"))  # fmt: skip
    for kind, name in kinds:
        if isinstance(value, kind):
            return name
    return type(value).__name__
