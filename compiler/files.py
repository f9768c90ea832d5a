"""Reading the files a user names, and writing output files so that nothing is ever
half-written; both fail with one message that says what to do.

Every result glint writes to a path a user named (`compose -o`, `render -o`, `lint --fix`, the
mesh and `--split` files, bench and site outputs) goes through `write_atomic`, which writes only
what it owns: a regular file. It refuses a device, a FIFO, a socket, a folder and a read-only
file; it writes through a symlink to its target; it keeps a file's mode, owner, group and hard
links; and the null device is written to, never replaced.
"""

from __future__ import annotations

import contextlib
import os
import re
import stat
import tempfile
from pathlib import Path

from glint.compiler.errors import EnvironmentProblem, InputError

# The writer's temporary files: hidden, named so that nobody mistakes them for work of their
# own, and skipped by `glint lint` when it searches a folder (a SIGKILL can leave one behind).
TEMP_PREFIX = ".glint-tmp-"
# What glint's writer called them before (mkstemp's eight characters, the output's suffix).
_OLD_TEMP = re.compile(r"\.glint-[a-z0-9_]{8}(\.[^.]*)?")

_KINDS = (
    (stat.S_ISDIR, "a folder", "name a file inside it"),
    (stat.S_ISCHR, "a character device", "choose a regular file (or - for standard output)"),
    (stat.S_ISBLK, "a block device", "choose a regular file (or - for standard output)"),
    (stat.S_ISFIFO, "a FIFO (named pipe)", "choose a regular file (or - for standard output)"),
    (stat.S_ISSOCK, "a socket", "choose a regular file (or - for standard output)"),
)


MiB = 1 << 20


def read_user_file(
    path: str | Path, limit: int, what: str = "file", follow_links: bool = True
) -> bytes:
    """The bytes of a file the user named, read only when it is a regular file of at most
    `limit` bytes; else an InputError saying why. A device (/dev/zero), a FIFO or a socket is
    refused before it is read (it could be endless or block forever); the file is opened
    without blocking, so that a FIFO swapped in after the check cannot hang the read either,
    and checked again on the open descriptor. `what` names the kind of file in messages.
    Without `follow_links`, a symbolic link is refused too (a file glint wrote itself, such as
    a cache entry, is never one)."""
    path = Path(path)
    flags = os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0)
    if not follow_links:
        flags |= getattr(os, "O_NOFOLLOW", 0)
    try:
        _check_regular(path, os.stat(path) if follow_links else os.lstat(path), limit, what)
        fd = os.open(path, flags)
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


# A shader is text a person wrote: the largest in the shared corpus is far under this.
SHADER_LIMIT = 16 * MiB


def read_text_file(path: str | Path) -> str:
    """The UTF-8 text of a shader file the user named, or an InputError saying why not (a
    device, a FIFO or a file past SHADER_LIMIT is refused before it is read)."""
    return read_user_text(path, SHADER_LIMIT, "shader file")


def is_temporary(name: str) -> bool:
    """Whether a file name is one of the writer's temporary files (or an older glint's)."""
    return name.startswith(TEMP_PREFIX) or _OLD_TEMP.fullmatch(name) is not None


def is_null_device(path: str | os.PathLike[str]) -> bool:
    """Whether `path` is (or links to) the null device, which outputs may be thrown into."""
    real = os.path.realpath(path)
    try:
        return real == os.devnull and stat.S_ISCHR(os.stat(real).st_mode)
    except OSError:
        return False


def write_atomic(path: str | os.PathLike[str], data: bytes) -> None:
    """Write `data` to the regular file `path`, whole: a reader sees the old content or the new,
    and a failure leaves the old file as it was and no temporary file behind (save one: a file
    rewritten in place that fails half-way, whose new content then stays in the temporary file
    that the message names).

    The content goes first to a temporary file beside the target, synced. A file that glint
    may simply replace (ours, one name) is then renamed over, with its mode; a file with other
    hard links, or another owner or group, is rewritten in place from that temporary copy, so
    its inode, owner, group, mode and links stay. A symlink is written through (it stays a link);
    the null device is opened and written to. Anything else that is not a regular file, and a
    read-only file, is refused with an EnvironmentProblem that says what to do.
    """
    shown = os.fspath(path)
    real = Path(os.path.realpath(path))
    before = _existing(shown, real)
    if before is not None and is_null_device(real):
        _write_null(shown, data)
        return
    if before is not None:
        _refuse_unless_writable_file(shown, real, before)
    in_place = before is not None and (
        before.st_nlink > 1 or before.st_uid != os.geteuid() or before.st_gid != os.getegid()
    )
    temp: str | None = None
    try:
        fd, temp = tempfile.mkstemp(prefix=TEMP_PREFIX, dir=real.parent)
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        if in_place:
            assert before is not None
            try:
                _overwrite(shown, real, before, data)
            except _Incomplete as exc:
                kept, temp = temp, None  # it alone holds the new content now: it stays
                raise EnvironmentProblem(
                    f"cannot write {shown}: {exc}; it is incomplete now, and its new content "
                    f"is in {kept}: copy that over it once the problem is solved"
                ) from exc.__cause__
        else:
            # mkstemp makes the file private (0600): a file replaced keeps its mode, a new
            # one gets the mode any new file gets
            os.chmod(temp, stat.S_IMODE(before.st_mode) if before else 0o666 & ~_umask())
            os.replace(temp, real)
            temp = None
            _sync_folder(real.parent)
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise EnvironmentProblem(f"cannot write {shown}: {reason}; choose a writable path") from exc
    finally:
        if temp is not None:
            _remove(temp)


def _existing(shown: str, real: Path) -> os.stat_result | None:
    """What `real` is now (not following a link), None when nothing is there."""
    try:
        found = os.lstat(real)
    except FileNotFoundError:
        return None
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise EnvironmentProblem(f"cannot write {shown}: {reason}; choose a writable path") from exc
    if stat.S_ISLNK(found.st_mode):  # realpath stops at a loop of links
        raise EnvironmentProblem(
            f"cannot write {shown}: its symlinks form a loop; fix the links or choose another path"
        )
    return found


def _refuse_unless_writable_file(shown: str, real: Path, found: os.stat_result) -> None:
    for test, kind, advice in _KINDS:
        if test(found.st_mode):
            raise EnvironmentProblem(f"cannot write {shown}: it is {kind}, not a file; {advice}")
    if not stat.S_ISREG(found.st_mode):
        raise EnvironmentProblem(
            f"cannot write {shown}: it is not a regular file; choose a regular file"
        )
    mode = stat.S_IMODE(found.st_mode)
    # root may write anything, so access() says yes to root: the mode's write bits say whether
    # the owner meant the file to be written
    writable = mode & 0o222 and os.access(real, os.W_OK, effective_ids=_effective_ids())
    if not writable:
        raise EnvironmentProblem(
            f"cannot write {shown}: it is read-only (mode {mode:04o}); make it writable "
            f"(chmod u+w) or write elsewhere"
        )


class _Incomplete(Exception):
    """Rewriting a file in place failed after it was truncated."""


def _overwrite(shown: str, real: Path, before: os.stat_result, data: bytes) -> None:
    """Rewrite `real` in place with `data` (whose full copy is already in a temporary file):
    the same inode, so its links, owner, group and mode stay."""
    fd = os.open(real, os.O_WRONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    try:
        now = os.fstat(fd)
        same = (now.st_dev, now.st_ino) == (before.st_dev, before.st_ino)
        if not same or not stat.S_ISREG(now.st_mode):
            raise EnvironmentProblem(
                f"cannot write {shown}: it changed while glint was writing it; run again"
            )
        try:
            os.ftruncate(fd, 0)
            view = memoryview(data)
            while view:
                view = view[os.write(fd, view) :]
            os.fsync(fd)
        except OSError as exc:
            raise _Incomplete(exc.strerror or str(exc)) from exc
        except BaseException as exc:  # interrupted half-way: say where the content is
            raise _Incomplete("interrupted") from exc
    finally:
        os.close(fd)


def _write_null(shown: str, data: bytes) -> None:
    try:
        with open(os.devnull, "wb") as handle:  # opened, never renamed over
            handle.write(data)
    except OSError as exc:
        reason = exc.strerror or str(exc)
        raise EnvironmentProblem(f"cannot write {shown}: {reason}") from exc


def _remove(temp: str) -> None:
    with contextlib.suppress(FileNotFoundError):
        os.unlink(temp)


def _sync_folder(folder: Path) -> None:
    """Make the rename durable; a folder that cannot be opened or synced is not an error."""
    try:
        fd = os.open(folder, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _effective_ids() -> bool:
    return os.access in os.supports_effective_ids


def _umask() -> int:
    mask = os.umask(0)  # reading the umask means setting it: set it back at once
    os.umask(mask)
    return mask
