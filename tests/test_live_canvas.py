"""The live canvases' pages and files, without a browser (tests/test_site_canvas.py runs them)."""

from __future__ import annotations

from pathlib import PurePosixPath

from glint.compiler.compose.uniform_params import read_manifest
from glint.compiler.site.live_canvas import (
    DEFAULT_SHADER,
    SCRIPT,
    canvas_html,
    live_files,
    live_path,
    live_section,
)
from glint.compiler.site.pictures import Picture


def test_a_canvas_names_its_shader_and_holds_no_shader_text() -> None:
    page = canvas_html(PurePosixPath("img/live/a&b.glsl"), (384, 216), 'say "hi"')
    assert 'data-shader="img/live/a&amp;b.glsl"' in page
    assert 'width="384" height="216"' in page and 'data-time="1"' in page
    assert 'aria-label="say &quot;hi&quot;"' in page


def test_a_variant_page_gets_a_canvas_only_with_a_live_shader() -> None:
    assert live_section("D.ggx", None) == ""
    assert live_section("D.ggx", Picture(note="no picture")) == ""
    section = live_section("D.ggx", Picture(live="void main() {}"))
    assert section.startswith("## Live\n")
    assert 'data-shader="img/live/D.ggx.glsl"' in section
    assert "void main" not in section


def test_files_hold_the_script_and_each_live_shader() -> None:
    files = live_files({"D.ggx": Picture(live="// live"), "core.constants": Picture()})
    assert files[live_path("D.ggx")] == b"// live"
    assert live_path("core.constants") not in files
    assert b"WEBGL_lose_context" in files[SCRIPT]
    default = files[DEFAULT_SHADER].decode()
    assert default.startswith("#version 300 es") and read_manifest(default)
