"""glint lint on real ShaderToy shaders (../shared/corpus, beside the checkout): no false errors,
and the findings judged by reading the code (tests/lint/labelled) hold — the wrong ones are gone,
the ones worth acting on are still reported, the default rules are the precise ones."""

from __future__ import annotations

import json
from typing import Any

import pytest

from glint.lint.precision import (
    CORPUS,
    DEFAULT_PRECISION,
    DEFAULT_SAMPLE,
    DEFAULT_SET_PRECISION,
    MIN_JUDGED,
    Label,
    corpus_findings,
    default_sample,
    load_labels,
    load_measured,
    measure,
    valid_files,
)
from glint.lint.rules import all_rules

pytestmark = pytest.mark.skipif(
    not (CORPUS / "glslang-valid.txt").is_file(),
    reason=f"the real-shader corpus is not at {CORPUS} (../shared/corpus beside the checkout)",
)


@pytest.fixture(scope="module")
def findings() -> list[dict[str, Any]]:
    """Every rule on every glslang-valid corpus file, glslang off (one run for the module)."""
    return corpus_findings(valid_files())


def test_no_error_on_shaders_glslang_accepts(findings: list[dict[str, Any]]) -> None:
    errors = [f for f in findings if f["severity"] == "error"]
    shown = "\n".join(f"{f['file']}:{f['line']}: {f['code']} {f['message']}" for f in errors[:20])
    assert not errors, f"{len(errors)} error findings on valid shaders:\n{shown}"


def test_labels_point_at_the_corpus_as_it_is() -> None:
    for label in load_labels():
        lines = (CORPUS / "shadertoy" / label.file).read_text(encoding="utf-8").split("\n")
        assert lines[label.line - 1].strip() == label.text, (label.code, label.file, label.line)


def test_findings_judged_wrong_are_gone_from_the_default_rules(
    findings: list[dict[str, Any]],
) -> None:
    """A default rule reports none of the findings judged wrong. The opt-in rules still report
    some (the analysis cannot follow them yet): how many is pinned, rule by rule, in the stored
    measurement that test_stored_precision_is_current holds current."""
    reported = {(f["code"], f["file"], f["line"], f["column"]) for f in findings}
    rules = all_rules()
    wrong = [lb for lb in load_labels() if lb.verdict == "wrong" and rules[lb.code].default]
    still = [lb for lb in wrong if lb.key in reported]
    shown = "\n".join(f"{lb.code} {lb.file}:{lb.line}: {lb.reason}" for lb in still)
    assert not still, f"{len(still)} findings judged wrong are still reported:\n{shown}"


def test_findings_worth_acting_on_are_still_reported(findings: list[dict[str, Any]]) -> None:
    reported = {(f["code"], f["file"], f["line"], f["column"]) for f in findings}
    lost = [lb for lb in load_labels() if lb.verdict == "worth" and lb.key not in reported]
    shown = "\n".join(f"{lb.code} {lb.file}:{lb.line}: {lb.reason}" for lb in lost)
    assert not lost, f"{len(lost)} findings worth acting on are no longer reported:\n{shown}"


def test_the_default_rules_are_the_precise_ones(findings: list[dict[str, Any]]) -> None:
    """A judged rule runs by default exactly when at least MIN_JUDGED of its findings on the
    corpus are labelled and DEFAULT_PRECISION of them are worth acting on: one that fires
    rarely or never has no measured precision and stays opt-in, whatever it scores."""
    stats = measure(load_labels(), findings)
    for code, rule in all_rules().items():
        if not rule.judged:
            continue
        s = stats[code]
        precise = (
            s.labelled >= MIN_JUDGED
            and s.precision is not None
            and s.precision >= DEFAULT_PRECISION
        )
        shown = "no" if s.precision is None else f"{s.precision:.0%}"
        assert rule.default == precise, (
            f"{code}: {shown} precision over {s.labelled} labelled findings, "
            f"but the rule is {'default' if rule.default else 'opt-in'}"
        )


def test_stored_precision_is_current(findings: list[dict[str, Any]]) -> None:
    stats = measure(load_labels(), findings)
    stored = load_measured().get("rules", {})
    fresh = {code: s.as_json() for code, s in stats.items()}
    assert json.dumps(stored, sort_keys=True) == json.dumps(fresh, sort_keys=True), (
        "regenerate: python -m glint.lint.precision --write, then "
        "glint rule --all --markdown > site/docs/rules.md"
    )


def test_the_default_findings_are_labelled_and_worth_acting_on(
    findings: list[dict[str, Any]],
) -> None:
    """Issue 26: of the default rules' findings on the corpus, a labelled sample of at least
    DEFAULT_SAMPLE (all of them if fewer) is worth acting on at DEFAULT_SET_PRECISION or more."""
    sample = default_sample(load_labels(), findings)
    shown = "\n".join(
        f"{f['code']} {f['file']}:{f['line']}:{f['column']}" for f in sample.unlabelled[:20]
    )
    assert sample.enough, (
        f"{sample.labelled} of {sample.count} default findings labelled; label at least "
        f"{min(sample.count, DEFAULT_SAMPLE)} (tests/lint/labelled). Unlabelled:\n{shown}"
    )
    assert sample.precision is not None and sample.precision >= DEFAULT_SET_PRECISION, sample.line()


def test_the_default_sample_counts_only_default_findings_and_their_labels() -> None:
    """default_sample on made-up findings: opt-in rules are left out, a finding without a
    label makes the sample short, and the verdicts give the precision."""
    default = next(code for code, rule in all_rules().items() if rule.default)
    opt_in = next(code for code, rule in all_rules().items() if not rule.default)

    def finding(code: str, line: int) -> dict[str, Any]:
        return {"code": code, "file": "a.glsl", "line": line, "column": 1}

    def label(line: int, verdict: str) -> Label:
        return Label(default, "a.glsl", line, 1, "x", verdict, "because")

    findings = [finding(default, n) for n in (1, 2, 3, 4, 5)] + [finding(opt_in, 9)]
    labels = [label(1, "worth"), label(2, "worth"), label(3, "worth"), label(4, "not-worth")]
    sample = default_sample(labels, findings)
    assert (sample.count, sample.labelled) == (5, 4)
    assert not sample.enough and sample.unlabelled == [findings[4]]
    sample = default_sample([*labels, label(5, "wrong")], findings)
    assert sample.enough and sample.precision == 0.6  # 3 of 5: below the bar
    assert "5 findings on the corpus, all labelled: 3 worth acting on" in sample.line()
