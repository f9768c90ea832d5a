"""The extra corpus is rebuilt from real git clones, file by file, at the commits listed."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

from glint.lint.extra_corpus import MANIFEST, Entry, load_manifest, rebuild


def _git(repo: Path, *args: str) -> str:
    done = subprocess.run(["git", "-C", str(repo), *args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


@pytest.fixture
def clones(tmp_path: Path) -> tuple[Path, str]:
    repo = tmp_path / "clones" / "someone+shaders"
    (repo / "tabs").mkdir(parents=True)
    (repo / "tabs" / "image.glsl").write_text("void mainImage(out vec4 c, in vec2 p) {}\n")
    (repo / "tabs" / "tunnel #2.glsl").write_text("// a # in a plain file's name\n")
    export = [
        {"info": {"id": "abcd12"}, "renderpass": [{"type": "buffer", "code": "// buffer A"}]},
        {
            "info": {"id": "Xy3zW1"},
            "renderpass": [
                {"type": "common", "code": "// common tab"},
                {"type": "image", "code": "// image tab"},
            ],
        },
    ]
    (repo / "export.json").write_text(json.dumps({"Shaders": 2, "Results": export}))
    _git(repo, "init", "-q")
    _git(repo, "add", "-A")
    _git(repo, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "one")
    commit = _git(repo, "rev-parse", "HEAD")
    (repo / "tabs" / "image.glsl").write_text("changed later\n")  # the commit, not the tree
    return tmp_path / "clones", commit


def test_rebuild_takes_each_file_at_its_commit(tmp_path: Path, clones: tuple[Path, str]) -> None:
    folder, commit = clones
    entries = [
        Entry("a.glsl", "someone/shaders", commit, "tabs/image.glsl", "MIT", "valid"),
        Entry("b.glsl", "someone/shaders", commit, "tabs/gone.glsl", "MIT", "valid"),
        Entry("c.glsl", "nobody/else", commit, "x.glsl", "none stated", "invalid"),
        Entry("d.glsl", "someone/shaders", commit, "export.json#Xy3zW1", "MIT", "valid"),
        Entry("d.common.glsl", "someone/shaders", commit, "export.json#Xy3zW1", "MIT", "common"),
        Entry("e.glsl", "someone/shaders", commit, "export.json#abcd12", "MIT", "valid"),
        Entry("f.glsl", "someone/shaders", commit, "tabs/tunnel #2.glsl", "MIT", "invalid"),
    ]
    out = tmp_path / "out"
    problems = rebuild(folder, out, entries)
    assert (out / "shadertoy" / "a.glsl").read_text().startswith("void mainImage")
    assert (out / "shadertoy" / "d.glsl").read_text() == "// image tab"
    assert (out / "shadertoy" / "d.common.glsl").read_text() == "// common tab"
    assert (out / "shadertoy" / "f.glsl").read_text().startswith("// a # in")
    # b: no such file; c: no clone; e: that shader has no Image pass
    assert [p.split(":")[0] for p in problems] == ["b.glsl", "c.glsl", "e.glsl"]
    assert (out / "glslang-valid.txt").read_text().split() == ["a.glsl", "d.glsl"]


def test_the_manifest_reads_and_names_each_file_once() -> None:
    entries = load_manifest(MANIFEST)
    assert len(entries) >= 1000
    assert len({e.name for e in entries}) == len(entries)
    assert all(len(e.commit) == 40 and "/" in e.repo for e in entries)
    assert not any(e.repo.lower().startswith("wurishi/") for e in entries)  # the corpus's source
