"""Reading the files a user names, and writing output files so that nothing is ever
half-written; both fail with one message that says what to do."""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

from glint.compiler.errors import EnvironmentProblem, InputError


def read_text_file(path: str | Path) -> str:
    """The UTF-8 text of a file the user named (a shader), or an InputError saying why not."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a folder, expected a shader file") from None
    except UnicodeDecodeError:
        raise InputError(f"{path}: not UTF-8 text; is it a shader?") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror}") from None


def write_atomic(path: str | Path, data: bytes) -> None:
    """Write `data` to `path` through a temporary file in the same folder and a rename: a reader
    sees the old file or the new one, and a failure leaves no partial file behind."""
    path = Path(path)
    temp_path: str | None = None
    try:
        fd, temp_path = tempfile.mkstemp(prefix=".glint-", suffix=path.suffix, dir=path.parent)
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        # mkstemp makes the file private (0600): a file replaced keeps its mode, a new one gets
        # the mode any new file gets
        os.chmod(temp_path, _mode_for(path))
        os.replace(temp_path, path)
    except OSError as exc:
        if temp_path is not None and os.path.exists(temp_path):
            os.unlink(temp_path)
        reason = exc.strerror or str(exc)
        raise EnvironmentProblem(f"cannot write {path}: {reason}; choose a writable path") from exc


def _mode_for(path: Path) -> int:
    try:
        return stat.S_IMODE(path.stat().st_mode)
    except FileNotFoundError:
        return 0o666 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)  # reading the umask means setting it: set it back at once
    os.umask(mask)
    return mask
