"""The live canvases' pages and files, without a browser (tests/e2e/test_site_canvas.py runs
them)."""

from __future__ import annotations

import re
from pathlib import PurePosixPath

from glint.compiler.compose.linking.uniform_params import read_manifest
from glint.compiler.site.live_canvas import (
    DEFAULT_SHADER,
    EDITOR_SCRIPT,
    SCRIPT,
    canvas_html,
    live_files,
    live_path,
    live_section,
    shadertoy_path,
    slot_live_section,
)
from glint.compiler.site.pictures import Picture, editable_code, picture_composition


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


def test_a_variant_page_edits_its_code_in_one_html_block() -> None:
    code = "// a < b\n\nfloat f() { return 1.0; }\n"
    section = live_section("D.ggx", Picture(live="// live", code=code))
    block = section[section.index('<div class="glint-edit"') :]
    assert "\n\n" not in block.rstrip("\n")  # a blank line would end Markdown's HTML block
    assert "// a &lt; b&#10;&#10;float f()" in block
    assert 'data-shader="img/live/D.ggx.glsl"' in block
    assert 'data-shadertoy="img/live/D.ggx.shadertoy.glsl"' in block
    assert "data-search-exclude" in block  # the code is on the page once more, for search
    assert "glint-edit" not in live_section("D.ggx", Picture(live="// live"))


def test_the_edited_code_stands_once_in_both_shaders_and_ships_with_them() -> None:
    shader, _ = picture_composition("D", "ggx")
    live = shader.retarget("webgl2", params_as_uniforms=True).text
    code = editable_code(shader, "D.ggx", live)
    assert "float distribution(" in code and "#version" not in code
    assert shader.text.count(code) == 1 and live.count(code) == 1
    assert editable_code(shader, "D.beckmann", live) == ""  # not in this composition
    picture = Picture(live=live, shader=shader.text, code=code)
    files = live_files({"D.ggx": picture}, editor=b"/* editor */")
    assert files[shadertoy_path("D.ggx")] == shader.text.encode()
    assert files[EDITOR_SCRIPT] == b"/* editor */"
    assert EDITOR_SCRIPT not in live_files({})


def test_a_slot_page_has_one_canvas_with_a_selector_of_its_live_variants() -> None:
    pictures = {
        "D.ggx": Picture(live="// ggx"),
        "D.beckmann": Picture(live="// beckmann"),
        "D.gaussian": Picture(note="no picture"),  # no live shader: not offered
    }
    ids = ["D.beckmann", "D.gaussian", "D.ggx"]
    section = slot_live_section("D", ids, pictures, "D.ggx")
    assert section.count("<canvas") == 1 and section.count("<select") == 1
    assert 'data-shader="img/live/D.ggx.glsl"' in section  # starts on the reference's variant
    options = re.findall(r'<option value="([^"]+)"( selected)?>([^<]+)</option>', section)
    assert options == [
        ("img/live/D.beckmann.glsl", "", "D.beckmann"),
        ("img/live/D.ggx.glsl", " selected", "D.ggx"),
    ]
    # without the reference's picture it starts on the first variant that has one
    first = slot_live_section("D", ids, pictures, "D.blinn_phong")
    assert 'data-shader="img/live/D.beckmann.glsl"' in first
    assert slot_live_section("D", ["D.gaussian"], pictures, "D.ggx") == ""


def test_the_tiers_page_has_a_live_tab_per_tier_for_each_scene() -> None:
    from glint.compiler.catalog.tiers import TIERS
    from glint.compiler.site.scene_pages import example_scenes, is_mesh_example, tiers_page

    stems = [scene.stem for scene in example_scenes() if not is_mesh_example(scene)]
    live = {(stem, tier): live_path(f"scene-{stem}-{tier}") for stem in stems for tier in TIERS}
    del live[(stems[0], TIERS[0])]  # a scene that did not compose at a tier has no tab for it
    page = tiers_page({}, {}, {}, live)
    for stem in stems:
        section = page.split(f"### {stem}\n", 1)[1].split("### ", 1)[0]
        tabs = re.findall(r'^=== "(\w+)"\n\n    <div class="glint-live">', section, re.M)
        assert tabs == [t for t in TIERS if (stem, t) in live]
        for tier in tabs:
            assert f'data-shader="img/live/scene-{stem}-{tier}.glsl"' in section
    # a mesh scene has no ShaderToy shader: no section and no canvas, a note instead
    assert "### eight_models\n" not in page and "scene-eight_models" not in page
    assert "Mesh scenes (eight_models) are not here" in page
