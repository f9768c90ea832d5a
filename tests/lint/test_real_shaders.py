"""glint lint on real ShaderToy shaders (../shared/corpus, beside the checkout): no false errors,
and the findings judged by reading the code (tests/lint/labelled) hold — the wrong ones are gone,
the ones worth acting on are still reported, the default rules are the precise ones."""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

import pytest

from glint.lint.precision import (
    CORPUS,
    DEFAULT_SAMPLE,
    DEFAULT_SET_PRECISION,
    EXTRA_CORPUS,
    EXTRA_LABELS,
    Label,
    RuleStats,
    combined,
    corpus_findings,
    default_sample,
    has_extra_corpus,
    load_labels,
    load_measured,
    measure,
    stored_extra,
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
        lines = (
            (CORPUS / "shadertoy" / label.file)
            .read_text(encoding="utf-8", errors="surrogateescape")
            .split("\n")
        )
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


@pytest.fixture(scope="module")
def extra_findings() -> list[dict[str, Any]] | None:
    """Every rule on the extra corpus (None where it is absent, as in CI)."""
    return corpus_findings(valid_files(EXTRA_CORPUS)) if has_extra_corpus() else None


def test_the_default_rules_are_the_precise_ones(
    findings: list[dict[str, Any]], extra_findings: list[dict[str, Any]] | None
) -> None:
    """A judged rule runs by default exactly when at least MIN_JUDGED of its findings on the
    corpora are labelled and DEFAULT_PRECISION of them are worth acting on: one that fires
    rarely or never has no measured precision and stays opt-in, whatever it scores. The extra
    corpus counts as measured now where it is present, as stored where it is not."""
    extra = (
        stored_extra()
        if extra_findings is None
        else measure(load_labels(EXTRA_LABELS), extra_findings)
    )
    stats = combined(measure(load_labels(), findings), extra)
    for code, rule in all_rules().items():
        if not rule.judged:
            continue
        s = stats[code]
        precise = s.earns_default
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


needs_extra = pytest.mark.skipif(
    not has_extra_corpus(), reason=f"no extra corpus at {EXTRA_CORPUS} (optional test data)"
)


@needs_extra
def test_extra_labels_point_at_the_extra_corpus_as_it_is() -> None:
    for label in load_labels(EXTRA_LABELS):
        path = EXTRA_CORPUS / "shadertoy" / label.file
        lines = path.read_text(encoding="utf-8", errors="surrogateescape").split("\n")
        assert lines[label.line - 1].strip() == label.text, (label.code, label.file, label.line)


@needs_extra
def test_extra_judgements_hold_and_are_stored(
    extra_findings: list[dict[str, Any]] | None,
) -> None:
    """On the extra corpus too: no error where glslang accepts the file, the findings judged
    worth acting on are still reported, and the stored measurement is this one (the findings
    judged wrong that a default rule still makes there count against its precision, which
    test_the_default_rules_are_the_precise_ones holds to the bar)."""
    assert extra_findings is not None
    errors = [f for f in extra_findings if f["severity"] == "error" and f["code"] != "C005"]
    # C005: a byte that is not UTF-8 outside comments (in an `#if 0` block, say), which glslang
    # reads as bytes and glint declines to guess
    assert not errors, [f"{f['file']}:{f['line']}: {f['code']}" for f in errors]
    labels = load_labels(EXTRA_LABELS)
    reported = {(f["code"], f["file"], f["line"], f["column"]) for f in extra_findings}
    lost = [lb for lb in labels if lb.verdict == "worth" and lb.key not in reported]
    assert not lost, [f"{lb.code} {lb.file}:{lb.line}" for lb in lost]
    fresh = {code: s.as_json() for code, s in measure(labels, extra_findings).items()}
    stored = load_measured().get("extra", {}).get("rules", {})
    assert json.dumps(stored, sort_keys=True) == json.dumps(fresh, sort_keys=True), (
        "regenerate: python -m glint.lint.precision --write"
    )


def test_stats_of_two_corpora_add_up() -> None:
    """combined() adds the judged counts and verdicts rule by rule, and a stored measurement
    reads back as it was written: the default policy over two corpora rests on both."""
    a = RuleStats("X", 10, 4, 10, Counter({"worth": 7, "not-worth": 3}), Counter())
    b = RuleStats("X", 6, 5, 6, Counter({"worth": 6}), Counter())
    assert not a.earns_default  # 10 judged: too few, and 70 %
    both = combined({"X": a}, {"X": RuleStats.from_json("X", b.as_json())})["X"]
    assert (both.count, both.labelled, both.verdicts["worth"]) == (16, 16, 13)
    assert both.precision == 13 / 16 and both.earns_default
    assert combined({"X": a}, {})["X"] is a


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
