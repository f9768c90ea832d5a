"""Live WebGL2 canvases on the docs site: the shader of a page's picture, running in the reader's
browser, with a play button, a time slider and a slider per parameter (live-canvas.js).

Each canvas names its shader by a data attribute, relative to the site's root; the shader is a
file of its own under `img/live/`, composed with `--target webgl2 --params-as-uniforms` so that
the sliders set uniforms, and fetched by the script: no shader text goes into a page's HTML.
The Getting started page shows the default scene; each variant page the scene of its picture,
emitted again for webgl2 from the same composition (pictures.py), not composed twice. A slot's
page has one canvas with a selector of its variants' shaders, and the tiers page one canvas per
scene and tier, in tabs.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from importlib import resources
from pathlib import PurePosixPath

import glint
from glint.compiler.markdown import html_attr, html_text

from .pictures import TIME, Picture

LIVE_DIR = PurePosixPath("img") / "live"
SCRIPT = PurePosixPath("assets") / "live-canvas.js"  # mkdocs.yml lists it in extra_javascript
# CodeMirror, bundled from npm by `make editor` (site/editor); live-canvas.js loads it only on a
# page with an editor.
EDITOR_SCRIPT = PurePosixPath("assets") / "glint-editor.js"
DEFAULT_SHADER = LIVE_DIR / "default.glsl"
VARIANT_SIZE = (384, 216)  # twice the picture's: small enough for a software rasteriser
HOME_SIZE = (640, 360)


def live_path(snippet_id: str) -> PurePosixPath:
    return LIVE_DIR / f"{snippet_id}.glsl"


def shadertoy_path(snippet_id: str) -> PurePosixPath:
    """The picture's ShaderToy shader, which "Copy as ShaderToy" fetches and edits."""
    return LIVE_DIR / f"{snippet_id}.shadertoy.glsl"


def canvas_html(
    shader: PurePosixPath,
    size: tuple[int, int],
    label: str,
    choices: Sequence[tuple[str, PurePosixPath]] = (),
    extra_class: str = "",
) -> str:
    """The raw HTML of one canvas: its drawing size, its shader (root-relative) and its time.
    With `choices` (a name and a shader each), a selector above it swaps the shader;
    `extra_class` is added to its box's classes."""
    width, height = size
    chooser = ""
    if choices:
        chooser = (
            f'<select class="glint-live-choice" aria-label="{html_attr(label)}: shader">'
            f"{_options(choices, shader)}</select>\n"
        )
    classes = f"glint-live {extra_class}".strip()
    return (
        f'<div class="{classes}">\n'
        + chooser
        + f'<canvas class="glint-live-canvas" width="{width}" height="{height}" '
        f'data-shader="{html_attr(shader.as_posix())}" data-time="{TIME:g}" '
        f'aria-label="{html_attr(label)}"></canvas>\n'
        "</div>\n"
    )


def _options(choices: Sequence[tuple[str, PurePosixPath]], selected: PurePosixPath) -> str:
    """A selector's options: a name and a shader each, `selected` chosen."""
    return "".join(
        f'<option value="{html_attr(path.as_posix())}"'
        f"{' selected' if path == selected else ''}>{html_text(name)}</option>"
        for name, path in choices
    )


def live_section(snippet_id: str, picture: Picture | None) -> str:
    """A variant page's Live section (at the picture's time, so its first frame is the
    picture), or "" when the variant has no picture and so no live shader."""
    if picture is None or not picture.live:
        return ""
    return (
        "## Live\n\n"
        "The picture's shader running in your browser (WebGL2), composed with "
        "`--target webgl2 --params-as-uniforms`: press Play, scrub the time, drag on it for "
        "`iMouse`, or move a parameter's slider.\n\n"
        + canvas_html(live_path(snippet_id), VARIANT_SIZE, f"{snippet_id}, live")
        + "\n"
        + edit_html(snippet_id, picture.code)
    )


def edit_html(snippet_id: str, code: str) -> str:
    """The variant's code in an editor under its canvas (CodeMirror, loaded by live-canvas.js
    only on a page that has one): an edit recompiles the canvas's shader with the code in the
    variant's place, a compile error shows at its line in the editor, and "Copy as ShaderToy"
    copies the picture's ShaderToy shader with the edit. Without the editor's script the code
    stays a read-only block. "" where the variant's code has no single place in its shaders."""
    if not code:
        return ""
    # line breaks as character references: a <pre> shows them, and no blank line ends the block
    lines = html_text(code)
    shader = html_attr(live_path(snippet_id).as_posix())
    return (
        "Edit the code and the canvas recompiles with it (a compile error shows at its line); "
        "**Copy as ShaderToy** copies the whole shader with your edit, ready for ShaderToy's "
        "Image tab.\n\n"
        f'<div class="glint-edit" data-search-exclude data-shader="{shader}" '
        f'data-shadertoy="{html_attr(shadertoy_path(snippet_id).as_posix())}">'
        f'<pre class="glint-edit-code"><code>{lines}</code></pre>'
        '<div class="glint-edit-tools">'
        '<button type="button" class="md-button glint-edit-copy">Copy as ShaderToy</button> '
        '<button type="button" class="md-button glint-edit-reset">Reset</button> '
        '<span class="glint-edit-status" role="status"></span></div></div>\n\n'
    )


def _live_choices(
    ids: Sequence[str], pictures: Mapping[str, Picture]
) -> list[tuple[str, PurePosixPath]]:
    """The variants among `ids` that have a live shader, each with its shader's path."""
    return [(id_, live_path(id_)) for id_ in ids if id_ in pictures and pictures[id_].live]


def slot_live_section(
    slot: str, ids: Sequence[str], pictures: Mapping[str, Picture], first: str | None
) -> str:
    """A slot page's Live section: one canvas and a selector of the variants that have a live
    shader, starting on `first` (the reference tier's variant) where it has one."""
    choices = _live_choices(ids, pictures)
    if not choices:
        return ""
    start = live_path(first) if first is not None and first in dict(choices) else choices[0][1]
    return (
        "## Live\n\n"
        "Each variant's picture shader running in your browser (WebGL2): pick a variant to "
        "swap it in; Play, the time slider, a drag for `iMouse` and the parameter sliders work "
        "as on the variant pages.\n\n"
        + canvas_html(start, VARIANT_SIZE, f"slot {slot}, live", choices)
        + "\n"
    )


def slot_compare_section(
    slot: str, ids: Sequence[str], pictures: Mapping[str, Picture], first: str | None
) -> str:
    """A slot page's A/B comparison: two variants' live shaders on one picture split by a
    divider the reader drags, and their difference amplified; the first pair is the reference
    tier's variant and the next one."""
    choices = _live_choices(ids, pictures)
    if len(choices) < 2:
        return ""
    paths = [path for _, path in choices]
    a = live_path(first) if first is not None and live_path(first) in paths else paths[0]
    b = next(path for path in paths if path != a)
    width, height = VARIANT_SIZE

    def chooser(which: str, selected: PurePosixPath) -> str:
        label = html_attr(f"slot {slot}: variant {which.upper()}")
        return (
            f'<select class="glint-compare-{which}" aria-label="{label}">'
            f"{_options(choices, selected)}</select>"
        )

    def canvas(which: str, shader: PurePosixPath) -> str:
        label = f"slot {slot}, variant {which.upper()}"
        return canvas_html(shader, VARIANT_SIZE, label, extra_class=f"glint-compare-{which}-view")

    return (
        "## Compare two variants\n\n"
        "Variant A on the left of the divider, B on the right, in the same scene, time and "
        "camera: drag the divider, or show where they differ, amplified. The sliders under the "
        "picture drive both.\n\n"
        '<div class="glint-compare">\n'
        f'<div class="glint-compare-choices">A {chooser("a", a)} B {chooser("b", b)}</div>\n'
        f'<div class="glint-compare-stage">{canvas("a", a)}{canvas("b", b)}'
        f'<canvas class="glint-compare-difference" width="{width}" height="{height}" hidden '
        f'aria-label="{html_attr(f"slot {slot}: |A - B|, amplified")}"></canvas></div>\n'
        '<div class="glint-compare-tools"><label>divider <input type="range" '
        'class="glint-compare-divider" min="0" max="100" value="50"></label> '
        '<label><input type="checkbox" class="glint-compare-show-difference"> |A − B| ×'
        '<select class="glint-compare-gain"><option>4</option><option selected>16</option>'
        "<option>64</option></select></label></div>\n"
        "</div>\n\n"
    )


def home_canvas() -> str:
    return canvas_html(DEFAULT_SHADER, HOME_SIZE, "the default scene, live")


def live_files(
    pictures: Mapping[str, Picture] | None = None, editor: bytes | None = None
) -> dict[PurePosixPath, bytes]:
    """The script, the default scene's live shader and each picture's (with its ShaderToy
    shader where the page edits it), and the editor's bundle when given, by path in the docs
    folder."""
    package = resources.files("glint.compiler.site")
    default = glint.compose(target="webgl2", params_as_uniforms=True).text
    files = {
        SCRIPT: (package / "live-canvas.js").read_bytes(),
        DEFAULT_SHADER: default.encode("utf-8"),
    }
    if editor is not None:
        files[EDITOR_SCRIPT] = editor
    for snippet_id, picture in (pictures or {}).items():
        if picture.live:
            files[live_path(snippet_id)] = picture.live.encode("utf-8")
        if picture.code:
            files[shadertoy_path(snippet_id)] = picture.shader.encode("utf-8")
    return files
