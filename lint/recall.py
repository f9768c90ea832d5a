"""How many of the serious defects that a reviewer finds by reading real shaders glint reports.

    python -m glint.lint.recall [CORPUS] [--select CODES]

The ground truth was made by reading, before any rule ran: reviewers read lit ShaderToy shaders
of `../shared/corpus/shadertoy` line by line and recorded, in `tests/lint/recall/*.toml`, every
file they read (`[[read]]`) and every serious defect in it (`[[defect]]`: file, line, the line's
text, a class, why it is wrong and the reachable input that shows it). A defect counts as found
when a rule that addresses its class reports on its line. Recall is printed for the default rules
and for every rule (`ALL`), overall and by class, with the defects missed.

This is the number issue 26 holds the linter to; precision on the same corpus is measured by
`python -m glint.lint.precision` from its own labels.
"""

from __future__ import annotations

import argparse
import sys
import tomllib
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from .options import Options
from .runner import lint_bytes

ROOT = Path(__file__).resolve().parents[1]
GROUND_TRUTH = ROOT / "tests" / "lint" / "recall"
CORPUS = ROOT.parent / "shared" / "corpus"

# The rules that address each class of defect: a finding of another rule on the same line is a
# coincidence, not the defect found. "other" is any rule.
CLASS_RULES: dict[str, frozenset[str]] = {
    "unwritten-out-or-return": frozenset({"C001", "C101", "C103", "C104", "C105"}),
    "uninitialised-read": frozenset({"C101", "C102", "C103", "C104"}),
    "domain-pow": frozenset({"N001", "N012", "N020"}),
    "domain-acos-asin": frozenset({"N003", "N012"}),
    "domain-sqrt-log": frozenset({"N002", "N012"}),
    "division-by-zero": frozenset({"N005", "N007", "N011"}),
    "fresnel-wrong-vector": frozenset({"L001", "L009"}),
    "half-vector-wrong": frozenset({"L001", "L002", "L009"}),
    "light-vector-wrong": frozenset({"L002"}),
    "unnormalized-normal": frozenset({"N006", "PF003"}),
    "mediump-precision": frozenset({"P001", "P002", "P003", "P004", "P005", "P006", "P007"}),
    "loop-exit-invariant": frozenset(),
    "minmax-clamp-noop": frozenset({"N008"}),
    "clamp-argument-order": frozenset({"N008", "N010"}),
    "copy-paste-twin": frozenset({"C108", "C109"}),
    "loop-invariant-expensive": frozenset({"PF002", "PF004"}),
    "es300-portability": frozenset(
        {"C001", "P001", "P002", "P003", "P004", "P005", "P006", "P007"}
    ),
    "index-out-of-range": frozenset({"C001"}),
    "other": frozenset(),  # any rule on the line
}
CLASSES = tuple(CLASS_RULES)
CONFIDENCES = ("certain", "likely")
# What a second, independent reading of a defect found (absent: it confirmed it). A
# host-dependent defect is real on ShaderToy, the corpus's target and glint's, but not on the
# host the corpus was collected from (a port that sets its own uniforms from a GUI).
SECOND_READINGS = ("host-dependent", "doubtful", "not-a-defect", "misreading")
CONFIRMED = (None, "host-dependent")


@dataclass(frozen=True)
class Defect:
    file: str
    line: int
    text: str
    kind: str  # one of CLASSES
    impact: str
    why: str
    trigger: str
    confidence: str
    second_reading: str | None = None  # one of SECOND_READINGS; None: confirmed
    second_reading_note: str = ""

    def found_by(self, codes_on_line: set[str]) -> set[str]:
        """The codes among those reported on this defect's line that address its class."""
        wanted = CLASS_RULES[self.kind]
        return codes_on_line if not wanted else codes_on_line & wanted


@dataclass(frozen=True)
class GroundTruth:
    read: tuple[str, ...]  # every file read, with or without a defect
    defects: tuple[Defect, ...]


def load_ground_truth(folder: Path = GROUND_TRUTH) -> GroundTruth:
    """Every file read and every defect recorded, checked for known classes and confidences and
    for defects only in files that were read."""
    read: list[str] = []
    defects: list[Defect] = []
    for path in sorted(folder.glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        read += [entry["file"] for entry in data.get("read", [])]
        for entry in data.get("defect", []):
            defect = Defect(
                entry["file"],
                int(entry["line"]),
                entry["text"],
                entry["class"],
                entry.get("impact", ""),
                entry["why"],
                entry["trigger"],
                entry.get("confidence", "certain"),
                entry.get("second_reading"),
                entry.get("second_reading_note", ""),
            )
            where = f"{path.name}: {defect.file}:{defect.line}"
            if defect.kind not in CLASS_RULES:
                raise ValueError(f"{where}: class {defect.kind!r} is not one of {CLASSES}")
            if defect.confidence not in CONFIDENCES:
                raise ValueError(f"{where}: confidence {defect.confidence!r} is unknown")
            if defect.second_reading not in (None, *SECOND_READINGS):
                raise ValueError(f"{where}: second_reading {defect.second_reading!r} is unknown")
            defects.append(defect)
    unread = {d.file for d in defects} - set(read)
    if unread:
        raise ValueError(f"defects recorded in files not marked as read: {sorted(unread)}")
    return GroundTruth(tuple(dict.fromkeys(read)), tuple(defects))


def codes_by_line(file: Path, options: Options) -> dict[int, set[str]]:
    """The codes each line of `file` is reported with."""
    found: dict[int, set[str]] = {}
    for finding in lint_bytes(file.read_bytes(), file.name, options).findings:
        found.setdefault(finding.line, set()).add(finding.code)
    return found


@dataclass
class Recall:
    found: list[tuple[Defect, set[str]]]
    missed: list[Defect]

    @property
    def share(self) -> float:
        total = len(self.found) + len(self.missed)
        return len(self.found) / total if total else 0.0

    def confirmed(self) -> Recall:
        """The same measure on the defects a second reading confirmed (SECOND_READINGS)."""
        return Recall(
            [(d, c) for d, c in self.found if d.second_reading in CONFIRMED],
            [d for d in self.missed if d.second_reading in CONFIRMED],
        )


def measure(truth: GroundTruth, corpus: Path, options: Options) -> Recall:
    files = corpus / "shadertoy"
    reported = {name: codes_by_line(files / name, options) for name in truth.read}
    recall = Recall([], [])
    for defect in truth.defects:
        codes = defect.found_by(reported[defect.file].get(defect.line, set()))
        if codes:
            recall.found.append((defect, codes))
        else:
            recall.missed.append(defect)
    return recall


def report(name: str, recall: Recall) -> str:
    total = len(recall.found) + len(recall.missed)
    lines = [f"{name}: {len(recall.found)} of {total} defects found ({recall.share:.0%})"]
    by_class: Counter[str] = Counter(d.kind for d in recall.missed)
    found_class: Counter[str] = Counter(d.kind for d, _ in recall.found)
    for kind in CLASSES:
        if by_class[kind] or found_class[kind]:
            seen = found_class[kind]
            lines.append(f"  {kind:<26} {seen} of {seen + by_class[kind]}")
    confirmed = recall.confirmed()
    lines.append(
        f"  confirmed by a second reading: {len(confirmed.found)} of "
        f"{len(confirmed.found) + len(confirmed.missed)} ({confirmed.share:.0%})"
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m glint.lint.recall", description=__doc__)
    parser.add_argument("corpus", nargs="?", type=Path, default=CORPUS)
    parser.add_argument("--missed", action="store_true", help="list the defects missed")
    args = parser.parse_args(argv)
    if not (args.corpus / "shadertoy").is_dir():
        print(f"no corpus at {args.corpus}/shadertoy", file=sys.stderr)
        return 2
    truth = load_ground_truth()
    contested = Counter(d.second_reading for d in truth.defects if d.second_reading)
    print(f"{len(truth.read)} shaders read, {len(truth.defects)} serious defects recorded; "
          f"a second reading contested some: {dict(sorted(contested.items()))}")  # fmt: skip
    for name, options in (("default rules", Options()), ("every rule (ALL)", Options(["ALL"]))):
        recall = measure(truth, args.corpus, options)
        print(report(name, recall))
        if args.missed:
            for d in recall.missed:
                print(f"    missed {d.file}:{d.line} [{d.kind}] {d.text}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
