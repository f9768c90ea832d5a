"""On a line where macros were expanded, findings point at the user's own columns and quote the
user's own text (`sin(iTime * PI)`, not `sin(iTime *  3.14159 )`); a node that a macro made
spans the macro's call."""

from __future__ import annotations

from glint.lint.options import Options
from glint.lint.runner import build_context, lint_source

SOURCE = """#define PI 3.14159
#define SCALE(x) (x) * 2.0
#define CAM pow(cos(iTime * PI), 2.0)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float c = CAM + pow(sin(iTime * PI), 3.0);
    float k = SCALE(c) + 1.0 / (iTime * PI);
    fragColor = vec4(c + k);
}
"""


def _findings(code: str) -> list[tuple[int, int, int, str]]:
    options = Options(select=[code], glslang=False)
    found = lint_source(SOURCE, "m.glsl", options)
    return [(f.line, f.column, f.end_column, f.message) for f in found]


def _line(n: int) -> str:
    return SOURCE.split("\n")[n - 1]


def test_a_finding_after_a_macro_points_at_the_users_columns_and_text() -> None:
    found = sorted(_findings("N001"))
    (line, col, end, message) = found[-1]  # the pow written out, after CAM on its line
    assert line == 5 and _line(5)[col - 1 : end - 1] == "sin(iTime * PI)"
    assert "pow base sin(iTime * PI) is negative" in message


def test_a_node_made_by_a_macro_spans_the_macros_call() -> None:
    found = sorted(_findings("N001"))
    (line, col, end, _) = found[0]  # the pow inside CAM
    assert line == 5 and _line(5)[col - 1 : end - 1] == "CAM"


def test_a_divisor_ending_in_an_object_macro_is_quoted_as_written() -> None:
    (finding,) = _findings("N011")
    line, col, end, message = finding
    assert _line(line)[col - 1 : end - 1] == "iTime * PI"
    assert "divides by iTime * PI," in message


def test_node_text_inside_a_function_macro_falls_back_to_the_expansion() -> None:
    """`(x) * 2.0` has no text of its own in the source: it is shown expanded; the whole call
    `SCALE(c)` is quoted as the user wrote it."""
    ctx = build_context(SOURCE, "m.glsl", Options(glslang=False))
    assert ctx.tree is not None
    texts = {ctx.node_text(n) for n in ctx.tree.iter_subtrees() if n.data == "binary"}
    assert "SCALE(c)" in texts  # the product the macro made, as its call
    assert "SCALE(c) + 1.0 / (iTime * PI)" in texts
    assert "iTime * PI" in texts  # written out on lines 5 and 6: quoted as written
    assert "iTime *  3.14159" in texts  # inside CAM: no text of its own, shown expanded


def test_columns_stay_on_the_users_line_after_a_splice() -> None:
    """A line continued with `\\` is one preprocessed line: a finding on it still points inside
    the line it reports (it used to point past its end)."""
    src = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    float v = 0.5 + \\\n"
        "        pow(sin(iTime), 3.0);\n"
        "    fragColor = vec4(v);\n"
        "}\n"
    )
    (finding,) = lint_source(src, "s.glsl", Options(select=["N001"], glslang=False))
    width = len(src.split("\n")[finding.line - 1]) + 1
    assert 1 <= finding.column <= width and finding.column <= finding.end_column <= width
    assert finding.fix is None  # no edit from approximate columns
