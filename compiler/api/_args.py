"""Checks of the API's arguments at its boundary: a wrong type or value is a `UsageError` that
names the argument and says what it takes, never a TypeError or ValueError from deep inside."""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Mapping, Sequence
from typing import Any

from glint.compiler.errors import UsageError


def _got(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _kind(value: object) -> str:
    return type(value).__name__


def text(name: str, value: object) -> str:
    """A non-empty str."""
    if not isinstance(value, str):
        raise UsageError(f"{name}: expected a str, got {_kind(value)} {_got(value)}")
    if not value.strip():
        raise UsageError(f"{name}: expected a non-empty str, got {value!r}")
    return value


def path(name: str, value: object) -> str:
    """A file system path: a non-empty str or os.PathLike naming a str path."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str):
        raise UsageError(f"{name}: expected a path (str or pathlib.Path), got {_kind(value)}")
    if not value.strip():
        raise UsageError(f"{name}: expected a path, got an empty str")
    if "\0" in value:
        raise UsageError(f"{name}: a path cannot hold a NUL character, got {_got(value)}")
    return value


def flag(name: str, value: object) -> bool:
    """True or False (numpy's bool too); not 1, "yes" or None."""
    kind = type(value)
    numpy_bool = kind.__module__ == "numpy" and kind.__name__ in ("bool", "bool_")
    if not (isinstance(value, bool) or numpy_bool):
        raise UsageError(f"{name}: expected True or False, got {_kind(value)} {_got(value)}")
    return bool(value)


def number(name: str, value: object) -> float:
    """A real number (int, float, numpy scalar; not a bool), finite."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise UsageError(f"{name}: expected a number, got {_kind(value)} {_got(value)}")
    try:
        result = float(value)
    except OverflowError:
        result = math.inf
    if not math.isfinite(result):
        raise UsageError(f"{name}: expected a finite number, got {_got(value)}")
    return result


def integer(name: str, value: object) -> int:
    """A whole number (int, numpy integer; not a bool or a float)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise UsageError(f"{name}: expected a whole number (int), got {_kind(value)} {_got(value)}")
    return int(value)


def numbers_of(name: str, value: object, count: int, whole: bool = False) -> list[Any]:
    """A sequence (tuple, list, numpy array) of exactly `count` numbers, each checked as
    `number` (or `integer` when `whole`)."""
    if isinstance(value, str | bytes) or not _is_sequence(value):
        raise UsageError(
            f"{name}: expected a sequence of {count} numbers, got {_kind(value)} {_got(value)}"
        )
    items = list(value)  # type: ignore[call-overload]
    if len(items) != count:
        raise UsageError(f"{name}: expected {count} numbers, got {len(items)}: {_got(value)}")
    check = integer if whole else number
    return [check(f"{name}[{index}]", item) for index, item in enumerate(items)]


def _is_sequence(value: object) -> bool:
    if isinstance(value, Sequence):
        return True
    return type(value).__name__ == "ndarray" and getattr(value, "ndim", 0) == 1


def choice(name: str, value: object, choices: Sequence[str]) -> str:
    """One of `choices`."""
    if not isinstance(value, str) or value not in choices:
        expected = ", ".join(choices)
        raise UsageError(f"{name}: unknown value {_got(value)}; expected one of {expected}")
    return value


def str_mapping(name: str, value: object) -> dict[str, str]:
    """A mapping of str to str, e.g. {slot: variant}; None is an empty one."""
    if value is None:
        return {}
    if not isinstance(value, Mapping):
        raise UsageError(
            f"{name}: expected a dict of str to str such as {{'shadow': 'hard'}}, got "
            f"{_kind(value)} {_got(value)}"
        )
    for key, item in value.items():
        if not isinstance(key, str) or not isinstance(item, str):
            raise UsageError(f"{name}: keys and values must be str, got {_got(key)}: {_got(item)}")
    return dict(value)


def channel_bindings(name: str, value: object) -> list[tuple[int, str]] | None:
    """None, or a mapping of channel number (0 to 3) to what it is bound to ("2d", "cube",
    "3d"), as (number, kind) pairs."""
    from glint.compiler.target.shadertoy import CHANNEL_KINDS, CHANNELS

    if value is None:
        return None
    if not isinstance(value, Mapping):
        raise UsageError(
            f"{name}: expected a dict of channel number to kind such as {{0: 'cube'}}, got "
            f"{_kind(value)} {_got(value)}"
        )
    bindings = []
    for number, kind in value.items():
        if isinstance(number, bool) or not isinstance(number, int) or not 0 <= number < CHANNELS:
            raise UsageError(f"{name}: channel numbers are 0 to {CHANNELS - 1}, got {_got(number)}")
        bindings.append((number, choice(f"{name}[{number}]", kind, tuple(CHANNEL_KINDS))))
    return bindings


def str_list(name: str, value: object) -> list[str] | None:
    """None, one str (comma-separated items) or a sequence of str."""
    if value is None:
        return None
    if isinstance(value, str):
        return value.split(",")
    if not isinstance(value, Sequence) or isinstance(value, bytes):
        raise UsageError(
            f"{name}: expected a str or a list of str, got {_kind(value)} {_got(value)}"
        )
    for item in value:
        if not isinstance(item, str):
            raise UsageError(f"{name}: every item must be a str, got {_kind(item)} {_got(item)}")
    return list(value)
