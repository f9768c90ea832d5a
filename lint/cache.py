"""The lint cache, like ruff's: a file whose bytes, name and lint settings are unchanged since
the last run gets its findings from `.glint_cache/` instead of being linted again.

An entry's key is a hash of everything its findings depend on:

- the file's bytes and its name (findings carry the name; per-file ignores match it);
- glint's version and a hash of the linter's own source (every file of the `glint.lint`
  package and of the GLSL front end, glslang runner and ShaderToy prelude it uses), so that
  any change to the code invalidates every entry;
- the effective options: select, ignore, per-file ignores, target, glslang on or off, and,
  with glslang on, which glslangValidator (its path, size and modification time).

Entries hold the findings as JSON (the `--format json` objects, fixes included), one file per
entry, written atomically (a temporary file renamed over the entry), so that an interrupted or
concurrent run never leaves half an entry; an entry that cannot be read is a miss. The cache is
never read when fixing (`--fix` lints fresh); `--no-cache` turns it off.

The directory is `.glint_cache/` beside the nearest pyproject.toml (the project's root), else in
the current directory; `--cache-dir` or `GLINT_CACHE_DIR` choose another. Entries live under a
folder named for the code's hash; folders of other versions of the code are removed when an
entry is first written.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import tempfile
from functools import cache
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from .finding import Edit, Finding, Fix
from .options import Options

DIRECTORY_NAME = ".glint_cache"
ENVIRONMENT_VARIABLE = "GLINT_CACHE_DIR"
FORMAT = "v1"  # the layout and the entry format; bump when either changes
_LINT_DIR = Path(__file__).resolve().parent
_COMPILER_DIR = _LINT_DIR.parent / "compiler"
# The parts of the compiler whose behaviour is part of the findings.
_COMPILER_SOURCES = ("glsl", "glslang.py", "shadertoy.py", "sourcemap.py", "errors.py")
_SOURCE_SUFFIXES = (".py", ".lark", ".json", ".toml")
_VERSION_FOLDER = re.compile(rf"^{FORMAT}-[0-9a-f]{{16}}$")


def cache_directory(explicit: str | None, pyproject: Path | None) -> Path:
    """Where the cache lives: `explicit` (--cache-dir), else $GLINT_CACHE_DIR, else
    `.glint_cache` beside the configuration's pyproject.toml, else in the current directory."""
    if explicit:
        return Path(explicit)
    if os.environ.get(ENVIRONMENT_VARIABLE):
        return Path(os.environ[ENVIRONMENT_VARIABLE])
    return (pyproject.parent if pyproject is not None else Path.cwd()) / DIRECTORY_NAME


@cache
def code_fingerprint() -> str:
    """A hash of glint's version and of the source files the findings depend on."""
    digest = hashlib.sha256()
    try:
        digest.update(version("glint").encode())
    except PackageNotFoundError:  # run from a checkout that is not installed
        digest.update(b"uninstalled")
    roots = [_LINT_DIR] + [_COMPILER_DIR / part for part in _COMPILER_SOURCES]
    for root in roots:
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


def _glslang_identity() -> str:
    """Which glslangValidator runs: a new one may report differently."""
    path = shutil.which("glslangValidator")
    if path is None:
        return "none"
    try:
        stat = os.stat(path)
    except OSError:
        return path
    return f"{path}:{stat.st_size}:{stat.st_mtime_ns}"


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
            "glslang": _glslang_identity() if options.glslang else False,
        }
        self._settings = json.dumps(settings, sort_keys=True).encode()
        self._prepared = False
        self.hits = 0
        self.misses = 0

    def key(self, name: str, data: bytes) -> str:
        digest = hashlib.sha256(self._settings)
        digest.update(b"\0" + name.encode("utf-8", "surrogateescape") + b"\0")
        digest.update(data)
        return digest.hexdigest()

    def load(self, key: str) -> list[Finding] | None:
        """The findings stored under `key`, or None (a miss)."""
        try:
            entry = json.loads((self.folder / f"{key}.json").read_bytes())
            findings = [finding_from_json(item) for item in entry["findings"]]
        except (OSError, ValueError, KeyError, TypeError):
            self.misses += 1
            return None
        self.hits += 1
        return findings

    def store(self, key: str, findings: list[Finding]) -> None:
        """Write the entry atomically: a temporary file in the same folder, renamed over it."""
        try:
            self._prepare()
            fd, tmp = tempfile.mkstemp(prefix=f".{key[:16]}.", suffix=".tmp", dir=self.folder)
            try:
                with os.fdopen(fd, "w", encoding="utf-8") as out:
                    json.dump({"findings": [f.as_json() for f in findings]}, out)
                os.replace(tmp, self.folder / f"{key}.json")
            except BaseException:
                Path(tmp).unlink(missing_ok=True)
                raise
        except OSError:
            pass  # a read-only or full disk: glint works without its cache

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
            if other != self.folder and other.is_dir() and _VERSION_FOLDER.match(other.name):
                shutil.rmtree(other, ignore_errors=True)


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
        fix=None
        if fix is None
        else Fix(
            message=fix["message"],
            edits=tuple(Edit(**edit) for edit in fix["edits"]),
            applicability=fix["applicability"],
        ),
    )
