"""The lint cache, like ruff's: a file whose bytes, name and lint settings are unchanged since
the last run gets its findings from `.glint_cache/` instead of being linted again.

An entry's key is a hash of everything its findings depend on:

- the file's bytes and its name (findings carry the name; per-file ignores match it), and
  the ShaderToy tab it is linted in: the Common tab's code in front of it (its name and
  content) or whether it is a Common tab itself, and the channels' types;
- glint's version and a hash of the linter's own source (every file of the `glint.lint`
  package, precision.json included, and of the compiler's GLSL front end `compiler/glsl/`, its
  targets, glslang runner and ShaderToy prelude `compiler/target/`, `compiler/errors.py` and
  `compiler/collector.py`), so that any change to the code invalidates every entry;
- the effective options: select, ignore, per-file ignores, target, channels, glslang on or
  off, and,
  with glslang on, which glslangValidator (its path, size, modification time and the version
  it prints).

Entries hold the findings as JSON (the `--format json` objects, fixes included), one file per
entry, written atomically (a temporary file renamed over the entry), so that an interrupted or
concurrent run never leaves half an entry. An entry is trusted only when it is what this code
wrote for this file: a regular file (never followed through a symbolic link, never larger than
MAX_ENTRY_BYTES), valid JSON of the entry's schema (every field of its type, a known rule code
and severity, lines and columns positive and within the file), and bound to the file: it names
the file, the SHA-256 of its bytes and the settings, and all three must match. Anything else is
a miss, and the entry is written anew. The cache is never read when fixing (`--fix` lints
fresh); `--no-cache` turns it off.

The directory is `.glint_cache/` beside the nearest pyproject.toml (the project's root), else in
the current directory; `--cache-dir` or `GLINT_CACHE_DIR` choose another. Entries live under a
folder named for the entry format and the code's hash; folders of other formats and versions of
the code are removed when an entry is first written.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import tempfile
from functools import cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from glint.compiler.errors import InputError
from glint.compiler.files import read_user_file
from glint.compiler.target.shadertoy import Tab

from .finding import CERTAINTIES, Edit, Finding, Fix
from .options import Options

DIRECTORY_NAME = ".glint_cache"
ENVIRONMENT_VARIABLE = "GLINT_CACHE_DIR"
FORMAT = "v2"  # the layout and the entry format; bump when either changes
# An entry larger than this is not written and not read: a file of 1 MB (the most lint
# analyses) with a finding on every line stays well under it.
MAX_ENTRY_BYTES = 32 << 20
_LINT_DIR = Path(__file__).resolve().parent
_COMPILER_DIR = _LINT_DIR.parent / "compiler"
# The parts of the compiler whose behaviour is part of the findings: the GLSL front end, the
# targets (the ShaderToy prelude that glslang compiles the file in, the glslang runner, source
# markers) and the errors. Lint imports nothing else of the compiler (a test checks).
_COMPILER_SOURCES = ("glsl", "target", "errors.py", "collector.py")
_SOURCE_SUFFIXES = (".py", ".lark", ".json", ".toml")
_VERSION_FOLDER = re.compile(r"^v\d+-[0-9a-f]{16}$")
_SEVERITIES = frozenset({"error", "warning", "info"})
_APPLICABILITY = frozenset({"safe", "unsafe"})
_ENTRY_KEYS = frozenset({"format", "file", "sha256", "settings", "findings"})
_FINDING_KEYS = frozenset(
    {
        "file",
        "line",
        "column",
        "end_line",
        "end_column",
        "code",
        "severity",
        "message",
        "certainty",
        "fix",
    }
)
_FIX_KEYS = frozenset({"message", "applicability", "edits"})
_EDIT_KEYS = frozenset({"line", "column", "end_line", "end_column", "content"})


def cache_directory(explicit: str | None, pyproject: Path | None) -> Path:
    """Where the cache lives: `explicit` (--cache-dir), else $GLINT_CACHE_DIR, else
    `.glint_cache` beside the configuration's pyproject.toml, else in the current directory."""
    if explicit:
        return Path(explicit)
    if os.environ.get(ENVIRONMENT_VARIABLE):
        return Path(os.environ[ENVIRONMENT_VARIABLE])
    return (pyproject.parent if pyproject is not None else Path.cwd()) / DIRECTORY_NAME


def fingerprint_roots() -> list[Path]:
    """The files and folders whose source the findings depend on."""
    return [_LINT_DIR] + [_COMPILER_DIR / part for part in _COMPILER_SOURCES]


@cache
def code_fingerprint() -> str:
    """A hash of glint's version and of the source files the findings depend on."""
    digest = hashlib.sha256()
    try:
        digest.update(version("glint").encode())
    except PackageNotFoundError:  # run from a checkout that is not installed
        digest.update(b"uninstalled")
    for root in fingerprint_roots():
        files = sorted(root.rglob("*")) if root.is_dir() else [root]
        for path in files:
            if path.suffix not in _SOURCE_SUFFIXES or "__pycache__" in path.parts:
                continue
            try:
                content = path.read_bytes()
            except OSError:
                continue
            digest.update(str(path.relative_to(_LINT_DIR.parent)).encode() + b"\0")
            digest.update(hashlib.sha256(content).digest())
    return digest.hexdigest()


@cache
def _glslang_identity() -> str:
    """Which glslangValidator runs, and the version it says it is: a new one may report
    differently, and a wrapper script keeps its size and time when what it runs changes."""
    path = shutil.which("glslangValidator")
    if path is None:
        return "none"
    try:
        info = os.stat(path)
        where = f"{path}:{info.st_size}:{info.st_mtime_ns}"
    except OSError:
        where = path
    try:
        run = subprocess.run([path, "--version"], capture_output=True, timeout=10, check=False)
        said = hashlib.sha256(run.stdout).hexdigest()[:16]
    except (OSError, subprocess.SubprocessError):
        said = "unknown"
    return f"{where}:{said}"


class LintCache:
    """Findings by content hash, in one directory; every method is best effort: a cache that
    cannot be read or written makes glint lint again, never fail."""

    def __init__(self, directory: Path, options: Options) -> None:
        self.root = directory
        self.folder = directory / f"{FORMAT}-{code_fingerprint()[:16]}"
        settings: dict[str, Any] = {
            "code": code_fingerprint(),
            "select": options.select,
            "ignore": options.ignore,
            "per_file_ignores": sorted(options.per_file_ignores.items()),
            "target": options.target,
            "channels": list(options.channels),
            "glslang": _glslang_identity() if options.glslang else False,
        }
        self._settings = json.dumps(settings, sort_keys=True).encode()
        self._settings_value = json.loads(self._settings)  # as an entry holds them
        self._prepared = False
        self.hits = 0
        self.misses = 0

    def key(self, name: str, data: bytes, tab: Tab | None = None) -> str:
        digest = hashlib.sha256(self._settings)
        digest.update(b"\0" + name.encode("utf-8", "surrogateescape") + b"\0")
        digest.update(data)
        if tab is not None and tab != Tab():  # the key of a file without a tab is unchanged
            world = [tab.common_file, tab.common, list(tab.channels), tab.is_common]
            digest.update(b"\0tab\0" + json.dumps(world).encode("utf-8", "surrogateescape"))
        return digest.hexdigest()

    def load(self, name: str, data: bytes, tab: Tab | None = None) -> list[Finding] | None:
        """The findings stored for the file `name` holding `data` in `tab`, or None (a miss):
        when there is no entry, or it is anything but what `store` writes for this file and
        settings."""
        raw = _read_entry(self.folder / f"{self.key(name, data, tab)}.json")
        findings = None
        if raw is not None:
            try:
                entry = json.loads(raw)
            except (ValueError, RecursionError):  # not JSON, or nested beyond the parser
                entry = None
            findings = self._findings(entry, name, data)
        if findings is None:
            self.misses += 1
            return None
        self.hits += 1
        return findings

    def store(
        self, name: str, data: bytes, findings: list[Finding], tab: Tab | None = None
    ) -> None:
        """Write the entry atomically: a temporary file in the same folder, renamed over it
        (over anything there: a broken entry, a symbolic link, a folder)."""
        entry = {
            "format": FORMAT,
            "file": name,
            "sha256": hashlib.sha256(data).hexdigest(),
            "settings": self._settings_value,
            "findings": [f.as_json() for f in findings],
        }
        if self._findings(entry, name, data) is None:
            return  # it would not be read back (a finding out of the file?): a miss next time
        content = json.dumps(entry).encode()  # ASCII: anything else is escaped
        if len(content) > MAX_ENTRY_BYTES:
            return
        path = self.folder / f"{self.key(name, data, tab)}.json"
        try:
            self._prepare()
            fd, tmp = tempfile.mkstemp(prefix=f".{path.stem[:16]}.", suffix=".tmp", dir=self.folder)
            try:
                with os.fdopen(fd, "wb") as out:
                    out.write(content)
                if path.is_dir() and not path.is_symlink():
                    shutil.rmtree(path, ignore_errors=True)
                os.replace(tmp, path)
            except BaseException:
                Path(tmp).unlink(missing_ok=True)
                raise
        except OSError:
            pass  # a read-only or full disk: glint works without its cache

    def _findings(self, entry: Any, name: str, data: bytes) -> list[Finding] | None:
        """The entry's findings when it is well formed and bound to this file and these
        settings; None otherwise."""
        if not (
            isinstance(entry, dict)
            and entry.keys() == _ENTRY_KEYS
            and entry["format"] == FORMAT
            and entry["file"] == name
            and entry["sha256"] == hashlib.sha256(data).hexdigest()
            and entry["settings"] == self._settings_value
            and isinstance(entry["findings"], list)
        ):
            return None
        bounds = _Bounds(data)
        if not all(bounds.finding_ok(item, name) for item in entry["findings"]):
            return None
        return [finding_from_json(item) for item in entry["findings"]]

    def _prepare(self) -> None:
        """Create the folder on first write; mark the cache as one (CACHEDIR.TAG, a .gitignore
        that ignores everything) and drop the folders of other versions of the code."""
        if self._prepared:
            return
        self._prepared = True
        self.folder.mkdir(parents=True, exist_ok=True)
        ignore = self.root / ".gitignore"
        if not ignore.exists():
            ignore.write_text("# Created by glint lint automatically.\n*\n", encoding="utf-8")
        tag = self.root / "CACHEDIR.TAG"
        if not tag.exists():
            tag.write_text(
                "Signature: 8a477f597d28d172789f06886806bc55\n"
                "# This file is a cache directory tag created by glint lint.\n",
                encoding="utf-8",
            )
        for other in self.root.iterdir():
            if (
                other != self.folder
                and _VERSION_FOLDER.match(other.name)
                and other.is_dir()
                and not other.is_symlink()
            ):
                shutil.rmtree(other, ignore_errors=True)


def _read_entry(path: Path) -> bytes | None:
    """The bytes of an entry, or None when there is none or it is not a regular file of at most
    MAX_ENTRY_BYTES: a symbolic link is not followed (to /dev/zero it would be read until
    memory runs out), a FIFO is not waited on."""
    try:
        return read_user_file(path, MAX_ENTRY_BYTES, "cache entry", follow_links=False)
    except InputError:
        return None


class _Bounds:
    """What a finding of a file may hold: lines from 1 to the file's line count (a line break
    being LF or CR, whichever counts more), columns from 1 to its length, a known rule code
    and severity."""

    def __init__(self, data: bytes) -> None:
        from .rules import rule_codes  # the codes without importing the rules

        self.lines = max(data.count(b"\n"), data.count(b"\r")) + 1
        self.columns = len(data) + 1
        self.codes = rule_codes()

    def span_ok(self, item: dict[str, Any]) -> bool:
        numbers = (item["line"], item["column"], item["end_line"], item["end_column"])
        if not all(type(n) is int for n in numbers):  # bool is an int, but not a position
            return False
        line, column, end_line, end_column = numbers
        return (
            1 <= line <= end_line <= self.lines
            and 1 <= column <= self.columns
            and 1 <= end_column <= self.columns
            and (end_line > line or end_column >= column)
        )

    def finding_ok(self, item: Any, name: str) -> bool:
        if not (isinstance(item, dict) and item.keys() == _FINDING_KEYS and self.span_ok(item)):
            return False
        fix = item["fix"]
        return (
            item["file"] == name
            and type(item["code"]) is str
            and item["code"] in self.codes
            and type(item["severity"]) is str
            and item["severity"] in _SEVERITIES
            and type(item["certainty"]) is str
            and item["certainty"] in CERTAINTIES
            and type(item["message"]) is str
            and (fix is None or self.fix_ok(fix))
        )

    def fix_ok(self, fix: Any) -> bool:
        return (
            isinstance(fix, dict)
            and fix.keys() == _FIX_KEYS
            and type(fix["message"]) is str
            and type(fix["applicability"]) is str
            and fix["applicability"] in _APPLICABILITY
            and isinstance(fix["edits"], list)
            and all(
                isinstance(edit, dict)
                and edit.keys() == _EDIT_KEYS
                and type(edit["content"]) is str
                and self.span_ok(edit)
                for edit in fix["edits"]
            )
        )


def finding_from_json(item: dict[str, Any]) -> Finding:
    """The inverse of `Finding.as_json`."""
    fix = item.get("fix")
    return Finding(
        file=item["file"],
        line=item["line"],
        column=item["column"],
        end_line=item["end_line"],
        end_column=item["end_column"],
        code=item["code"],
        severity=item["severity"],
        message=item["message"],
        certainty=item["certainty"],
        fix=None
        if fix is None
        else Fix(
            message=fix["message"],
            edits=tuple(Edit(**edit) for edit in fix["edits"]),
            applicability=fix["applicability"],
        ),
    )
