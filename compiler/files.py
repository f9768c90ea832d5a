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


MiB = 1 << 20


def read_user_file(path: str | Path, limit: int, what: str = "file") -> bytes:
    """The bytes of a file the user named, read only when it is a regular file of at most
    `limit` bytes; else an InputError saying why. A device (/dev/zero), a FIFO or a socket is
    refused before it is read (it could be endless or block forever); the file is opened
    without blocking, so that a FIFO swapped in after the check cannot hang the read either,
    and checked again on the open descriptor. `what` names the kind of file in messages."""
    path = Path(path)
    try:
        _check_regular(path, os.stat(path), limit, what)
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{path}: is a folder, expected a {what}") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror or exc}") from None
    try:
        _check_regular(path, os.fstat(fd), limit, what)
        chunks, size = [], 0
        while size <= limit:
            chunk = os.read(fd, min(limit + 1 - size, MiB))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror or exc}") from None
    finally:
        os.close(fd)
    if size > limit:  # it grew after the check
        raise _too_large(path, size, limit, what)
    return b"".join(chunks)


def read_user_text(path: str | Path, limit: int, what: str = "file") -> str:
    """read_user_file, decoded as UTF-8 (one message for a file that is not)."""
    data = read_user_file(path, limit, what)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text (byte {exc.start}); is it a {what}?") from None


def _check_regular(path: Path, info: os.stat_result, limit: int, what: str) -> None:
    if stat.S_ISDIR(info.st_mode):
        raise InputError(f"{path}: is a folder, expected a {what}")
    if not stat.S_ISREG(info.st_mode):
        raise InputError(
            f"{path}: not a regular file (a device, a FIFO or a socket); glint reads a {what} "
            "only from a regular file"
        )
    if info.st_size > limit:
        raise _too_large(path, info.st_size, limit, what)


def _too_large(path: Path, size: int, limit: int, what: str) -> InputError:
    return InputError(
        f"{path}: {size / MiB:.1f} MiB, larger than the {limit / MiB:g} MiB glint reads for a "
        f"{what}; is it the right file?"
    )


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
