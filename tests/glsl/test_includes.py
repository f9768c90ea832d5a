"""`#include "file"` of local files in lint, validate and render: what is included is checked
as a compiler sees it, and every finding is reported at the included file and its line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from glint.compiler.errors import InputError
from glint.compiler.glsl.includes import expand_includes

GLINT = [sys.executable, "-m", "glint.compiler.cli"]
NOISE = (
    '#ifndef NOISE_GLSL\n#define NOISE_GLSL\n#include "const.glsl"\n'
    "float hash(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453 * K); }\n"
    "#endif\n"
)
CONST = "#ifndef CONST_GLSL\n#define CONST_GLSL\nconst float K = 1.0;\n#endif\n"
MAIN = (
    '#include "lib/noise.glsl"\n#include "lib/const.glsl"\n'
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "    fragColor = vec4(vec3(hash(fragCoord) * K), 1.0);\n}\n"
)


def _project(tmp_path: Path, noise: str = NOISE) -> Path:
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "noise.glsl").write_text(noise)
    (tmp_path / "lib" / "const.glsl").write_text(CONST)
    (tmp_path / "main.glsl").write_text(MAIN)
    return tmp_path / "main.glsl"


def _run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*GLINT, *args], capture_output=True, text=True, cwd=cwd)


def test_included_code_lints_validates_and_renders(tmp_path: Path) -> None:
    """Included twice (directly and through noise.glsl), const.glsl's guard keeps one copy."""
    main = _project(tmp_path)
    assert _run("lint", "--no-cache", str(main)).returncode == 0
    assert _run("validate", str(main)).returncode == 0
    done = _run("render", str(main), "-o", str(tmp_path / "out.png"), "--size", "32x18")
    assert done.returncode == 0, done.stderr


def test_an_error_in_an_included_file_is_reported_there(tmp_path: Path) -> None:
    noise = NOISE.replace("* K)", "* K + oops)")
    main = _project(tmp_path, noise)
    column = noise.split("\n")[3].index("oops") + 1
    where = f"{Path('lib') / 'noise.glsl'}:4:"  # relative to the folder the command runs in
    lint = _run("lint", "--no-cache", "--format", "concise", "main.glsl", cwd=tmp_path)
    assert lint.returncode == 1 and f"{where}{column}: C001" in lint.stdout
    assert "'oops'" in lint.stdout
    validate = _run("validate", "main.glsl", cwd=tmp_path)
    assert validate.returncode == 1 and f"{where}{column}: error: 'oops'" in validate.stdout
    render = _run("render", "main.glsl", "-o", "out.png", cwd=tmp_path)
    assert render.returncode == 1 and f"{where}{column}: error" in render.stderr
    assert main.exists() and not (tmp_path / "out.png").exists()


def test_a_cycle_and_a_missing_file_are_named(tmp_path: Path) -> None:
    (tmp_path / "a.glsl").write_text('#include "b.glsl"\n')
    (tmp_path / "b.glsl").write_text('// b\n#include "a.glsl"\n')
    with pytest.raises(
        InputError, match=r"b.glsl:2: #include 'a.glsl': a cycle \(a.glsl -> b.glsl -> a.glsl\)"
    ):
        expand_includes((tmp_path / "a.glsl").read_text(), str(tmp_path / "a.glsl"))
    done = _run("lint", str(tmp_path / "a.glsl"))  # a finding at the directive, C004
    assert done.returncode == 1 and "b.glsl:2:1: C004 #include 'a.glsl': a cycle" in done.stdout
    assert "Traceback" not in done.stderr
    (tmp_path / "c.glsl").write_text('#include "lib/none.glsl"\n')
    done = _run("validate", str(tmp_path / "c.glsl"))
    assert (
        done.returncode == 1 and "c.glsl:1: #include 'lib/none.glsl': no such file" in done.stderr
    )


def test_pragma_once_and_the_line_map(tmp_path: Path) -> None:
    (tmp_path / "once.glsl").write_text("#pragma once\nfloat one() { return 1.0; }\n")
    text = '#include "once.glsl"\n#include "once.glsl"\nfloat two() { return 2.0; }\n'
    expanded = expand_includes(text, str(tmp_path / "main.glsl"))
    assert expanded.text.count("float one()") == 1
    line = expanded.text.split("\n").index("float two() { return 2.0; }") + 1
    assert expanded.origin(line) == (str(tmp_path / "main.glsl"), 3)
    one = expanded.text.split("\n").index("float one() { return 1.0; }") + 1
    assert expanded.origin(one) == (str(tmp_path / "once.glsl"), 2)
