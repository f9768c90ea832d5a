"""Every rule has a fixture and an expected-output snapshot, as ruff's rules do:
tests/lint/fixtures/<CODE>.glsl, a small ShaderToy shader that triggers the rule and, commented,
a nearby case it must not report, and <CODE>.expected, the concise output of
`glint lint --no-glslang --select CODE <CODE>.glsl` run in the fixtures folder (glslang on for
the glslang rules C001 and C002, skipped where glslangValidator is not installed).

A rule without a fixture fails; output that differs from the snapshot fails with a diff.
`GLINT_UPDATE_SNAPSHOTS=1 pytest tests/lint/test_rule_fixtures.py` rewrites the snapshots:
read the diff before committing them."""

from __future__ import annotations

import difflib
import os
import re
import shutil
from pathlib import Path

import pytest

from glint.compiler.cli import main
from glint.lint.rules import all_rules

FIXTURES = Path(__file__).resolve().parent / "fixtures"
UPDATE = os.environ.get("GLINT_UPDATE_SNAPSHOTS") == "1"
NEEDS_GLSLANG = {"C001", "C002"}


def lint_output(code: str, capsys: pytest.CaptureFixture[str]) -> str:
    """What `glint lint` prints for the fixture, run in the fixtures folder."""
    argv = ["lint", "--select", code, "--format", "concise", f"{code}.glsl"]
    if code not in NEEDS_GLSLANG:
        argv.insert(1, "--no-glslang")
    capsys.readouterr()
    status = main(argv)
    out, err = capsys.readouterr()
    assert status in (0, 1), f"glint lint exited with {status}: {err}"
    return out


@pytest.mark.parametrize("code", list(all_rules()))
def test_rule_output_matches_its_snapshot(
    code: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    fixture = FIXTURES / f"{code}.glsl"
    assert fixture.is_file(), f"{code} has no fixture: write tests/lint/fixtures/{code}.glsl"
    assert b"not reported" in fixture.read_bytes().lower(), (
        f"{fixture.name}: show, commented, a nearby case the rule must not report"
    )
    if code in NEEDS_GLSLANG and shutil.which("glslangValidator") is None:
        pytest.skip("glslangValidator is not installed")
    monkeypatch.chdir(FIXTURES)
    out = lint_output(code, capsys)
    own = re.compile(rf"^{code}\.glsl:\d+:\d+: {code} ", re.M)
    assert own.search(out), f"{fixture.name} must trigger {code} at least once:\n{out}"
    snapshot = FIXTURES / f"{code}.expected"
    if UPDATE:
        snapshot.write_text(out, encoding="utf-8")
        return
    assert snapshot.is_file(), f"no snapshot: run with GLINT_UPDATE_SNAPSHOTS=1 to write {snapshot}"
    expected = snapshot.read_text(encoding="utf-8")
    if out != expected:
        diff = difflib.unified_diff(
            expected.splitlines(keepends=True),
            out.splitlines(keepends=True),
            f"{code}.expected",
            "glint lint output",
        )
        pytest.fail(
            f"{code}: output differs from its snapshot (GLINT_UPDATE_SNAPSHOTS=1 rewrites it)"
            f":\n{''.join(diff)}"
        )


def test_every_fixture_belongs_to_a_rule() -> None:
    codes = set(all_rules())
    stale = sorted(p.name for p in FIXTURES.iterdir() if p.stem not in codes)
    assert not stale, f"fixtures or snapshots of no registered rule: {stale}"
