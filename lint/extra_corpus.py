"""Rebuild the extra corpus of real shaders from the public repositories it was drawn from.

    python -m glint.lint.extra_corpus CLONES [OUT]

The extra corpus (see `precision.py`) holds ShaderToy Image tabs that other people published in
public GitHub repositories. Their licences differ and most allow no copy here, so the project
keeps only the list: `tests/lint/extra-corpus.tsv`, one row per file (name in the corpus, the
repository, the commit, the path there, the licence the repository states, and its kind: an
Image tab glslangValidator accepts under ShaderToy's prelude or not, or a Common tab, written
beside its image as NAME.common.glsl). A path `file.json#ID` is the pass of shader ID in a
ShaderToy JSON export (its `renderpass` list). CLONES is a folder of clones of those
repositories, each as `owner+name` or `owner/name`; the files are written to OUT/shadertoy (OUT
defaults to `../extra-corpus`, where precision.py looks), with OUT/glslang-valid.txt listing the
valid ones.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .precision import EXTRA_CORPUS, ROOT

MANIFEST = ROOT / "tests" / "lint" / "extra-corpus.tsv"


@dataclass(frozen=True)
class Entry:
    name: str  # the file's name in the corpus
    repo: str  # owner/name on GitHub
    commit: str
    path: str  # in the repository
    licence: str
    kind: str  # one of KINDS

    @property
    def valid(self) -> bool:
        return self.kind == "valid"


KINDS = ("valid", "invalid", "common")


def load_manifest(path: Path = MANIFEST) -> list[Entry]:
    """The manifest's rows (tab-separated; `#` starts a comment line)."""
    entries: list[Entry] = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cells = line.split("\t")
        if len(cells) != 6:
            raise ValueError(f"{path.name}:{number}: expected 6 tab-separated cells")
        name, repo, commit, file, licence, kind = cells
        if kind not in KINDS:
            raise ValueError(f"{path.name}:{number}: kind {kind!r} is not one of {KINDS}")
        entries.append(Entry(name, repo, commit, file, licence, kind))
    return entries


def clone_of(clones: Path, repo: str) -> Path | None:
    for candidate in (clones / repo.replace("/", "+"), clones / repo):
        for git in (candidate / "repo", candidate):
            if (git / "HEAD").is_file() or (git / ".git").exists():
                return git
    return None


def _shaders(node: Any) -> list[dict[str, Any]]:
    """Every shader (a dict with a `renderpass` list) in a ShaderToy JSON export: one shader,
    the API's `{"Shader": ...}` or a list of them."""
    if isinstance(node, dict):
        if isinstance(node.get("renderpass"), list):
            return [node]
        return [s for value in node.values() for s in _shaders(value)]
    if isinstance(node, list):
        return [s for value in node for s in _shaders(value)]
    return []


def pass_code(export: bytes, shader_id: str, kind: str) -> bytes | None:
    """The Image (or, for kind `common`, the Common) pass of shader `shader_id` in an export."""
    wanted = "common" if kind == "common" else "image"
    for shader in _shaders(json.loads(export)):
        if str((shader.get("info") or {}).get("id", "")) != shader_id:
            continue
        for p in shader["renderpass"]:
            if isinstance(p, dict) and p.get("type") == wanted and isinstance(p.get("code"), str):
                return p["code"].encode("utf-8")
    return None


def rebuild(clones: Path, out: Path, entries: list[Entry]) -> list[str]:
    """Write every entry found in the clones; return the problems (missing clone or blob)."""
    folder = out / "shadertoy"
    folder.mkdir(parents=True, exist_ok=True)
    problems: list[str] = []
    for e in entries:
        git = clone_of(clones, e.repo)
        if git is None:
            problems.append(f"{e.name}: no clone of {e.repo} in {clones}")
            continue
        file, _, shader_id = e.path.rpartition("#")
        if not file.endswith(".json"):  # a `#` in a plain file's own name
            file, shader_id = e.path, ""
        shown = subprocess.run(
            ["git", "-C", str(git), "show", f"{e.commit}:{file}"],
            capture_output=True,
            check=False,
        )
        code = shown.stdout if shown.returncode == 0 else None
        if code is not None and shader_id:
            code = pass_code(code, shader_id, e.kind)
        if code is None:
            problems.append(f"{e.name}: {e.repo}@{e.commit[:10]}:{e.path} is not there")
            continue
        (folder / e.name).write_bytes(code)
    valid = sorted(e.name for e in entries if e.valid and (folder / e.name).is_file())
    (out / "glslang-valid.txt").write_text("\n".join(valid) + "\n", encoding="utf-8")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m glint.lint.extra_corpus", description=__doc__)
    parser.add_argument("clones", type=Path, help="a folder of clones (owner+name or owner/name)")
    parser.add_argument("out", type=Path, nargs="?", default=EXTRA_CORPUS)
    args = parser.parse_args(argv)
    if not args.clones.is_dir():
        print(f"extra_corpus: {args.clones} is not a folder of clones", file=sys.stderr)
        return 2
    entries = load_manifest()
    problems = rebuild(args.clones, args.out, entries)
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"wrote {len(entries) - len(problems)} of {len(entries)} files to {args.out}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
