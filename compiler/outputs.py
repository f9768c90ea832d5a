"""Writing output files so that nothing is ever half-written."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from glint.compiler.errors import EnvironmentProblem


def write_atomic(path: str | Path, data: bytes) -> None:
    """Write `data` to `path` through a temporary file in the same folder and a rename: a reader
    sees the old file or the new one, and a failure leaves no partial file behind."""
    path = Path(path)
    temp_path: str | None = None
    try:
        fd, temp_path = tempfile.mkstemp(prefix=".glint-", suffix=path.suffix, dir=path.parent)
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(temp_path, path)
    except OSError as exc:
        if temp_path is not None and os.path.exists(temp_path):
            os.unlink(temp_path)
        reason = exc.strerror or str(exc)
        raise EnvironmentProblem(f"cannot write {path}: {reason}; choose a writable path") from exc
