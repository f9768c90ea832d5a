"""How far a variant's GPU output is from its reference: per-sample errors and their summary."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from glint.compiler.bench.samples import SIGNIFICANT, ProbeSet
from glint.compiler.verify.references.normals import angle_deg


@dataclass(frozen=True)
class ErrorSummary:
    max_abs: float
    rms: float  # over every component of every sample
    max_rel: float | None  # None where not asked for, or where no reference value is significant
    worst_at: dict[str, float]  # coordinates of the sample with the largest error
    samples: int
    # RMS error over the reference's own RMS: comparable between variants whose values differ in
    # scale (a D of 1e4 at its peak beside a V under 1); None where `max_rel` is
    rel_rms: float | None = None


def abs_errors(gpu: np.ndarray, exact: np.ndarray) -> np.ndarray:
    """|GPU − exact|, the reference broadcast over the GPU's components (a scalar reference of
    an RGB result holds for each channel). A NaN or infinite output is an infinite error."""
    gpu = np.asarray(gpu, np.float64)
    exact = np.asarray(exact, np.float64)
    if gpu.ndim == 2 and exact.ndim == 1:
        exact = exact[:, None]
    error = np.abs(gpu - np.broadcast_to(exact, gpu.shape))
    return np.where(np.isfinite(error), error, np.inf)


def relative_errors(error: np.ndarray, exact: np.ndarray) -> np.ndarray:
    """error / |exact| where |exact| is significant (> SIGNIFICANT); the other entries dropped."""
    exact = np.abs(np.asarray(exact, np.float64))
    if error.ndim == 2 and exact.ndim == 1:
        exact = exact[:, None]
    exact = np.broadcast_to(exact, error.shape)
    significant = exact > SIGNIFICANT
    return error[significant] / exact[significant]


def set_errors(probe_set: ProbeSet, gpu: np.ndarray) -> np.ndarray:
    """Per-sample (or per-component) error of one probe pass in the set's metric."""
    if probe_set.exact is None:
        raise ValueError("this probe set has no reference values")
    if probe_set.metric == "degrees":
        angle = angle_deg(np.asarray(gpu, np.float64), probe_set.exact)
        return np.where(np.isfinite(angle), angle, np.inf)
    return abs_errors(gpu, probe_set.exact)


def summarize(
    errors: list[np.ndarray],
    coordinates: list[dict[str, np.ndarray]],
    exact: list[np.ndarray] | None = None,
) -> ErrorSummary:
    """Pool the errors of several passes; `exact` (one per pass) asks for the relative error.
    Each pass's `coordinates` name its samples, for where the error is worst."""
    rows = [e if e.ndim == 1 else e.max(axis=1) for e in errors]
    pooled = np.concatenate(rows)
    worst = int(np.argmax(pooled))
    for error, where in zip(rows, coordinates, strict=True):
        if worst < len(error):
            worst_at = {key: float(values[worst]) for key, values in where.items()}
            break
        worst -= len(error)
    squares = np.concatenate([np.ravel(e) ** 2 for e in errors])
    max_rel = rel_rms = None
    rms = float(np.sqrt(squares.mean()))
    if exact is not None:
        relative = np.concatenate(
            [relative_errors(e, x) for e, x in zip(errors, exact, strict=True)]
        )
        max_rel = float(relative.max()) if relative.size else None
        scale = np.concatenate(
            [np.ravel(_broadcast(x, e)) ** 2 for e, x in zip(errors, exact, strict=True)]
        )
        reference_rms = float(np.sqrt(scale.mean()))
        rel_rms = rms / reference_rms if reference_rms > SIGNIFICANT else None
    return ErrorSummary(
        max_abs=float(pooled.max()),
        rms=rms,
        max_rel=max_rel,
        worst_at=worst_at,
        samples=len(pooled),
        rel_rms=rel_rms,
    )


def _broadcast(exact: np.ndarray, error: np.ndarray) -> np.ndarray:
    """The reference values in the shape of the errors (a scalar reference of an RGB result
    holds for each channel)."""
    exact = np.asarray(exact, np.float64)
    if error.ndim == 2 and exact.ndim == 1:
        exact = exact[:, None]
    return np.broadcast_to(exact, error.shape)
