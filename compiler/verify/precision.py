"""Which snippets survive float16 (mediump): the same code at half, single and double precision.

A snippet's entry is evaluated on a grid over its front-matter domain; float16 and float32 are
compared with float64. "finite" means finite wherever the float64 result is. Where a precision
is not, the report says where (the range of each input over the failing samples) and how many of
them have a true value beyond float16's largest finite number, which no float16 code can hold:
the others fail in an intermediate step.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.catalog.slots import SCENE_FUNCTIONS
from glint.compiler.compose.linking.snippet_evaluation import (
    entry_of,
    evaluate_snippet,
    snippet_source,
)
from glint.compiler.evaluator.errors import UnsupportedError
from glint.compiler.evaluator.interpreter import Interpreter

DTYPES: dict[str, Any] = {"float16": np.float16, "float32": np.float32, "float64": np.float64}
_DIRECTIONS = {"dir", "rd", "n", "N", "L", "V"}
_REL_FLOOR = 1e-6  # relative error is measured against max(|f64|, this)
HALF_MAX = 65504.0  # float16's largest finite number
SIMPLE_TYPES = {"float", "vec3", "Dots", "Surface"}


def default_map(p: np.ndarray) -> np.ndarray:
    """A stand-in scene: a unit sphere at (0, 1, 0) over the plane y = 0."""
    sphere = np.linalg.norm(p - np.array([0.0, 1.0, 0.0]), axis=-1) - 1.0
    return np.minimum(sphere, p[..., 1])


DEFAULT_EXTERNALS: dict[str, Any] = {
    "map": default_map,
    "SUN_DIR": np.array([0.48, 0.8, 0.36]),
    "SUN_COLOR": np.array([1.0, 0.95, 0.9]),
}


def entry_params(snippet_id: str) -> list[tuple[str, str, str]]:
    """(qualifier, type, name) of the snippet's entry function."""
    source, predefined = snippet_source(snippet_id)
    module = Interpreter(source, f"<{snippet_id}>", predefined, np.float64)
    return module.functions[entry_of(snippet_id)][0].params


def default_grid(snippet_id: str, points: int = 4096, seed: int = 0) -> dict[str, Any]:
    """Arguments over the domain: a tensor grid of the scalar dimensions (floats and struct
    fields named in `domain`), random unit directions or points for vec3s."""
    snippet = load_catalog().get(snippet_id)
    params = entry_params(snippet_id)
    domain = {k: tuple(map(float, v)) for k, v in snippet.domain.items()}
    dims: list[str] = []
    for _, type_, name in params:
        if type_ == "float" or (type_ == "vec3" and name in domain):
            dims.append(name)
        elif type_ in ("Dots", "Surface"):
            dims += [k for k in domain if k not in dims and k not in {n for *_, n in params}]
            dims += [k for k in ("a", "NoV") if k not in dims and type_ == "Surface"]
    dims = list(dict.fromkeys(dims))
    per_axis = max(2, int(round(points ** (1 / max(len(dims), 1)))))
    axes = [np.linspace(*domain.get(d, (0.0, 1.0)), per_axis) for d in dims]
    mesh = np.meshgrid(*axes, indexing="ij") if axes else []
    scalars = {d: m.ravel() for d, m in zip(dims, mesh, strict=True)}
    lanes = len(next(iter(scalars.values()))) if scalars else points
    rng = np.random.default_rng(seed)
    args: dict[str, Any] = {}
    for _, type_, name in params:
        if type_ == "float":
            args[name] = scalars[name]
        elif type_ == "vec3" and name in scalars:
            args[name] = np.repeat(scalars[name][:, None], 3, axis=1)  # grey
        elif type_ == "vec3" and name in _DIRECTIONS:
            v = rng.normal(size=(lanes, 3))
            args[name] = v / np.linalg.norm(v, axis=-1, keepdims=True)
        elif type_ == "vec3" and name in ("color", "F"):
            args[name] = rng.uniform(0.0, 8.0 if name == "color" else 1.0, size=(lanes, 3))
        elif type_ == "vec3":
            args[name] = rng.uniform(-2.0, 2.0, size=(lanes, 3)) + [0.0, 2.0, 0.0]
        elif type_ == "Dots":
            args[name] = _dots(scalars, lanes)
        elif type_ == "Surface":
            args[name] = _surface(scalars, lanes)
        else:
            raise ValueError(f"{snippet_id}: no grid for a {type_} parameter")
    return args


def _dots(s: dict[str, np.ndarray], lanes: int) -> dict[str, np.ndarray]:
    mid = np.full(lanes, 0.5)
    dots = {k: s.get(k, mid) for k in ("NoL", "NoV", "NoH", "VoH", "LoV")}
    dots["NoLsigned"] = s.get("NoLsigned", dots["NoL"])
    return dots


def _surface(s: dict[str, np.ndarray], lanes: int) -> dict[str, np.ndarray]:
    nov = np.clip(s.get("NoV", np.full(lanes, 0.5)), 1e-4, 1.0)
    a = s.get("a", np.full(lanes, 0.25))
    view = np.stack([np.sqrt(1 - nov**2), np.zeros(lanes), nov], -1)
    return {
        "P": np.zeros(3),
        "N": np.array([0.0, 0.0, 1.0]),
        "V": view,
        "diffuseColor": np.full(3, 0.5),
        "f0": np.full(3, 0.04),
        "roughness": np.sqrt(a),
        "a": a,
        "NoV": nov,
        "diffuseRoughness": np.sqrt(a),
    }


def precision_report(
    snippet_id: str,
    grid: dict[str, Any] | list[Any] | None = None,
    function: str | None = None,
    externals: dict[str, Any] | None = None,
) -> dict[str, dict[str, Any]]:
    """{dtype name: {"finite", "max_rel_err_vs_f64", "nonfinite_lanes"}} for the snippet's
    entry (or `function`) over `grid` (default: `default_grid`); where a precision is not
    finite, also "nonfinite_where" ({input: [min, max]} over the failing samples, for the
    inputs that vary) and "nonfinite_beyond_range" (how many of those samples have a float64
    value beyond float16's largest finite number)."""
    args = grid if grid is not None else default_grid(snippet_id)
    ext = {**DEFAULT_EXTERNALS, **(externals or {})}
    results = {
        name: np.asarray(evaluate_snippet(snippet_id, function, args, dt, ext), np.float64)
        for name, dt in DTYPES.items()
    }
    ref = results["float64"]
    ok = np.isfinite(ref)
    report: dict[str, dict[str, Any]] = {}
    for name, out in results.items():
        bad = ok & ~np.isfinite(out)
        with np.errstate(all="ignore"):
            rel = np.abs(out - ref) / np.maximum(np.abs(ref), _REL_FLOOR)
        rel = np.where(ok, np.where(np.isfinite(out), rel, np.inf), 0.0)  # nan counts as inf
        report[name] = {
            "finite": not bool(bad.any()),
            "max_rel_err_vs_f64": float(np.max(rel)) if rel.size else 0.0,
            "nonfinite_lanes": int(bad.sum()),
        }
        if bad.any():
            report[name] |= _where_not_finite(args, bad, ref)
    return report


def _where_not_finite(args: Any, bad: np.ndarray, ref: np.ndarray) -> dict[str, Any]:
    """Where a precision fails: the span of each varying input over the failing samples, and
    how many of them hold a true value that float16 cannot (|f64| > HALF_MAX)."""
    lanes = bad.reshape(len(bad), -1).any(axis=1)
    huge = np.abs(ref.reshape(len(ref), -1)).max(axis=1) > HALF_MAX
    where = {
        name: [float(values[lanes].min()), float(values[lanes].max())]
        for name, values in _scalar_inputs(args, len(lanes)).items()
        if values.min() != values.max()
    }
    return {"nonfinite_where": where, "nonfinite_beyond_range": int((lanes & huge).sum())}


def _scalar_inputs(args: Any, lanes: int, prefix: str = "") -> dict[str, np.ndarray]:
    """The arguments that hold one scalar per sample, by name (a struct's fields as
    `name.field`); vectors and constants are left out."""
    found: dict[str, np.ndarray] = {}
    items = args.items() if isinstance(args, dict) else ()
    for name, value in items:
        if isinstance(value, dict):
            found |= _scalar_inputs(value, lanes, f"{prefix}{name}.")
        elif isinstance(value, np.ndarray) and value.shape == (lanes,):
            found[f"{prefix}{name}"] = value
    return found


def survey(points: int = 4096) -> dict[str, dict[str, dict[str, Any]]]:
    """`precision_report` of every snippet whose slot entry takes only float, vec3, Dots and
    Surface parameters. Snippets that only a GPU can run (screen-space derivatives) are left
    out, and so are those that need a scene function other than `map`."""
    out: dict[str, dict[str, dict[str, Any]]] = {}
    for snippet in load_catalog().snippets.values():
        if any(n in SCENE_FUNCTIONS and n not in DEFAULT_EXTERNALS for n in snippet.requires):
            continue  # a closed-form scene query or span: only a composed scene has one
        try:
            params = entry_params(snippet.id)
        except ValueError:
            continue  # a library slot: no entry
        except UnsupportedError:
            continue  # a type the evaluator does not run (a picture's sampler2D)
        if all(q == "in" and t in SIMPLE_TYPES for q, t, _ in params):
            try:
                out[snippet.id] = precision_report(snippet.id, default_grid(snippet.id, points))
            except UnsupportedError:
                continue
    return out
