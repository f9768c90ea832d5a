"""The ground truth of serious defects found by reading real shaders (tests/lint/recall), and
the recall measurement that reads it (lint/recall.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from glint.lint.options import Options
from glint.lint.recall import CORPUS, GroundTruth, load_ground_truth, measure

SHADERS = CORPUS / "shadertoy"
needs_corpus = pytest.mark.skipif(
    not SHADERS.is_dir(), reason="the ShaderToy corpus is not beside the checkout (../shared)"
)


@needs_corpus
def test_every_recorded_defect_is_on_the_line_it_names() -> None:
    """A defect's text is its line in the corpus, so a label cannot drift from the code."""
    truth = load_ground_truth()
    assert len(truth.read) >= 100 and truth.defects
    for defect in truth.defects:
        lines = (SHADERS / defect.file).read_text(encoding="utf-8", errors="replace").splitlines()
        assert 1 <= defect.line <= len(lines), f"{defect.file}:{defect.line}: past the end"
        assert lines[defect.line - 1].strip() == defect.text.strip(), (
            f"{defect.file}:{defect.line}: the label's text is not that line"
        )
        assert defect.why.strip() and defect.trigger.strip()


def _write(folder: Path, text: str) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "part.toml").write_text(text, encoding="utf-8")


def test_a_defect_in_a_file_not_read_or_of_an_unknown_class_is_refused(tmp_path: Path) -> None:
    defect = '[[defect]]\nfile = "b.glsl"\nline = 1\ntext = "x"\nclass = "{}"\nwhy = "w"\n' \
        'trigger = "t"\n'  # fmt: skip
    _write(tmp_path / "unread", '[[read]]\nfile = "a.glsl"\n' + defect.format("domain-pow"))
    with pytest.raises(ValueError, match="not marked as read"):
        load_ground_truth(tmp_path / "unread")
    _write(tmp_path / "class", '[[read]]\nfile = "b.glsl"\n' + defect.format("pow-ish"))
    with pytest.raises(ValueError, match="class 'pow-ish'"):
        load_ground_truth(tmp_path / "class")


def test_a_defect_is_found_only_by_a_rule_of_its_class_on_its_line(tmp_path: Path) -> None:
    """pow of an unclamped dot (N001's class) on line 2; the same line also holds a division
    that a division rule may report: only N001 finds the pow defect."""
    shaders = tmp_path / "shadertoy"
    shaders.mkdir()
    source = (
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    vec3 n = normalize(vec3(p, 1.0)); float s = pow(dot(n, vec3(0.0, 0.0, -1.0)), 8.0);\n"
        "    c = vec4(s);\n"
        "}\n"
    )
    (shaders / "a.glsl").write_text(source, encoding="utf-8")
    truth = load_ground_truth_from(tmp_path, "a.glsl", 2, "domain-pow")
    assert len(measure(truth, tmp_path, Options(["N001"], glslang=False)).found) == 1
    assert len(measure(truth, tmp_path, Options(["N005"], glslang=False)).missed) == 1
    wrong_line = load_ground_truth_from(tmp_path, "a.glsl", 3, "domain-pow")
    assert len(measure(wrong_line, tmp_path, Options(["N001"], glslang=False)).missed) == 1


def load_ground_truth_from(folder: Path, file: str, line: int, kind: str) -> GroundTruth:
    _write(
        folder / "truth",
        f'[[read]]\nfile = "{file}"\n[[defect]]\nfile = "{file}"\nline = {line}\n'
        f'text = "-"\nclass = "{kind}"\nwhy = "w"\ntrigger = "t"\n',
    )
    return load_ground_truth(folder / "truth")
