"""Reading the files a user names and writing outputs whole (compiler/files.py)."""

from __future__ import annotations

import os
import socket
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from glint.compiler.errors import EnvironmentProblem, InputError
from glint.compiler.files import is_null_device, is_temporary, read_text_file, write_atomic


def test_an_output_gets_the_mode_a_new_file_gets(tmp_path: Path) -> None:
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "shader.glsl", b"void mainImage() {}\n")
    finally:
        os.umask(old)
    mode = stat.S_IMODE((tmp_path / "shader.glsl").stat().st_mode)
    assert mode == 0o644  # not mkstemp's 0600: others may read what glint wrote
    assert [p.name for p in tmp_path.iterdir()] == ["shader.glsl"]  # no temporary left


@pytest.mark.parametrize(
    ("make", "says"),
    [
        (lambda p: p, "no such file"),
        (lambda p: (p.mkdir(), p)[1], "is a folder"),
        (lambda p: (p.write_bytes(b"\xff\xfe\x00bad"), p)[1], "not UTF-8 text"),
    ],
)
def test_reading_a_bad_file_says_why(tmp_path: Path, make, says: str) -> None:  # type: ignore[no-untyped-def]
    path = make(tmp_path / "x.glsl")
    with pytest.raises(InputError, match=says):
        read_text_file(path)


def test_a_file_replaced_keeps_its_mode(tmp_path: Path) -> None:
    target = tmp_path / "shader.glsl"
    target.write_text("old\n")
    target.chmod(0o640)
    write_atomic(target, b"new\n")
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert target.read_text() == "new\n"


# The writer writes only what it owns: a regular file, through links, keeping what the file is.

ROOT = os.geteuid() == 0
needs_root = pytest.mark.skipif(not ROOT, reason="making devices and giving files away need root")


def _left(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@needs_root
def test_a_device_is_refused_and_stays_a_device(tmp_path: Path) -> None:
    device = tmp_path / "null"
    os.mknod(device, stat.S_IFCHR | 0o666, os.makedev(1, 3))
    with pytest.raises(EnvironmentProblem, match="null: it is a character device"):
        write_atomic(device, b"shader\n")
    assert stat.S_ISCHR(device.lstat().st_mode)
    assert _left(tmp_path) == ["null"]


def test_a_fifo_is_refused_without_opening_it(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.glsl"
    os.mkfifo(fifo)
    with pytest.raises(EnvironmentProblem, match=r"it is a FIFO \(named pipe\)"):
        write_atomic(fifo, b"shader\n")  # opening it to write would wait for a reader
    assert stat.S_ISFIFO(fifo.lstat().st_mode)
    assert _left(tmp_path) == ["pipe.glsl"]


def test_a_socket_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "s.glsl"
    if len(str(path)) > 100:
        pytest.skip("tmp path too long for a Unix socket")
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        with pytest.raises(EnvironmentProblem, match="it is a socket"):
            write_atomic(path, b"shader\n")
        assert stat.S_ISSOCK(path.lstat().st_mode)


def test_a_folder_is_refused(tmp_path: Path) -> None:
    folder = tmp_path / "out.glsl"
    folder.mkdir()
    with pytest.raises(EnvironmentProblem, match="it is a folder, not a file; name a file"):
        write_atomic(folder, b"shader\n")
    assert folder.is_dir() and _left(tmp_path) == ["out.glsl"]


def test_a_read_only_file_is_refused_even_to_root(tmp_path: Path) -> None:
    target = tmp_path / "shader.glsl"
    target.write_text("old\n")
    target.chmod(0o444)
    with pytest.raises(EnvironmentProblem, match=r"read-only \(mode 0444\); make it writable"):
        write_atomic(target, b"new\n")
    assert target.read_text() == "old\n"
    assert stat.S_IMODE(target.stat().st_mode) == 0o444
    assert _left(tmp_path) == ["shader.glsl"]


def test_a_symlink_is_written_through_and_stays_a_link(tmp_path: Path) -> None:
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "shader.glsl"
    target.write_text("old\n")
    target.chmod(0o640)
    link = tmp_path / "link.glsl"
    link.symlink_to(Path("real") / "shader.glsl")
    write_atomic(link, b"new\n")
    assert link.is_symlink() and os.readlink(link) == os.path.join("real", "shader.glsl")
    assert target.read_text() == "new\n"
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert _left(tmp_path / "real") == ["shader.glsl"] and _left(tmp_path) == ["link.glsl", "real"]


def test_a_dangling_symlink_creates_its_target(tmp_path: Path) -> None:
    link = tmp_path / "link.glsl"
    link.symlink_to("made.glsl")
    write_atomic(link, b"new\n")
    assert link.is_symlink() and (tmp_path / "made.glsl").read_text() == "new\n"


def test_a_symlink_loop_is_refused(tmp_path: Path) -> None:
    (tmp_path / "a").symlink_to("b")
    (tmp_path / "b").symlink_to("a")
    with pytest.raises(EnvironmentProblem, match="symlinks form a loop"):
        write_atomic(tmp_path / "a", b"new\n")


def test_hard_links_keep_sharing_the_file(tmp_path: Path) -> None:
    first = tmp_path / "shader.glsl"
    first.write_text("old\n")
    second = tmp_path / "copy.glsl"
    os.link(first, second)
    inode = first.stat().st_ino
    write_atomic(first, b"new, and longer than before\n")
    assert first.read_text() == second.read_text() == "new, and longer than before\n"
    assert first.stat().st_ino == second.stat().st_ino == inode
    assert first.stat().st_nlink == 2
    assert _left(tmp_path) == ["copy.glsl", "shader.glsl"]


@needs_root
def test_a_file_of_another_owner_keeps_its_owner_group_and_mode(tmp_path: Path) -> None:
    target = tmp_path / "theirs.glsl"
    target.write_text("old, longer than what replaces it\n")
    os.chown(target, 65534, 65534)
    target.chmod(0o600)  # only its owner may read it: root must not take it over
    write_atomic(target, b"new\n")
    after = target.stat()
    assert (after.st_uid, after.st_gid, stat.S_IMODE(after.st_mode)) == (65534, 65534, 0o600)
    assert target.read_text() == "new\n"
    assert _left(tmp_path) == ["theirs.glsl"]


def test_the_null_device_is_written_to_not_replaced(null_device: str) -> None:
    before = os.stat(null_device)
    write_atomic(null_device, b"thrown away\n")
    after = os.stat(null_device)
    assert stat.S_ISCHR(after.st_mode)
    assert (after.st_ino, after.st_rdev) == (before.st_ino, before.st_rdev)
    assert is_null_device(null_device)


def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path: Path) -> None:
    # A real failure: a file-size limit (RLIMIT_FSIZE) makes the data write fail with EFBIG,
    # in a child process so that the limit ends with it.
    plain = tmp_path / "plain.glsl"
    plain.write_text("old\n")
    linked = tmp_path / "linked.glsl"  # the in-place path: the original must stay whole too
    linked.write_text("old\n")
    os.link(linked, tmp_path / "other.glsl")
    child = textwrap.dedent(
        """
        import resource, signal, sys
        from glint.compiler.errors import EnvironmentProblem
        from glint.compiler.files import write_atomic
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
        for path in sys.argv[1:]:
            try:
                write_atomic(path, b"x" * 100_000)
            except EnvironmentProblem as exc:
                print(exc.message)
        """
    )
    done = subprocess.run(
        [sys.executable, "-c", child, str(plain), str(linked)],
        capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert len(lines) == 2 and all(line.startswith("cannot write ") for line in lines)
    assert plain.read_text() == linked.read_text() == "old\n"
    assert _left(tmp_path) == ["linked.glsl", "other.glsl", "plain.glsl"]


def test_an_interrupted_write_leaves_no_temporary(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Ctrl-C cannot be timed to land inside the write, so fsync is made to raise it there.
    target = tmp_path / "shader.glsl"
    target.write_text("old\n")

    def interrupted(fd: int) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write_atomic(target, b"new\n")
    assert target.read_text() == "old\n"
    assert _left(tmp_path) == ["shader.glsl"]


def test_temporary_names_are_recognised() -> None:
    assert is_temporary(".glint-tmp-x.glsl")
    assert is_temporary(".glint-ab_12xyz.glsl")  # what an older glint named them
    assert not is_temporary("glint-tmp-x.glsl")
    assert not is_temporary(".glint-config.glsl")
    assert not is_temporary("shader.glsl")


def test_a_shader_that_is_a_fifo_or_a_device_is_refused_unread(tmp_path: Path) -> None:
    """`glint validate` and `glint.render` read a shader through read_text_file: a FIFO would
    block forever and /dev/zero never ends, so neither is opened for reading."""
    fifo = tmp_path / "pipe.glsl"
    os.mkfifo(fifo)
    for path in (fifo, Path("/dev/zero")):
        with pytest.raises(InputError, match="not a regular file"):
            read_text_file(path)
