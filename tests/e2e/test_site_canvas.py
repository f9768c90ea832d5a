"""The docs site's live WebGL2 canvases in Debian's Chromium (SwiftShader): a canvas compiles and
draws what `glint render` draws for the same shader (mean FLIP under 0.01), its sliders change
the picture, a slot page's selector swaps the variant, a compile error shows at the user's line,
a tier's tab starts its canvas when opened, and a page reached by Material's instant navigation
starts its canvas.

The site is built here, once, with `site_url` set to the local server's address: Material's
instant navigation only takes links it finds in the sitemap, which `site_url` fills. The browser
and its pages come from tests/conftest.py (tests/site_browser.py).
"""

from __future__ import annotations

import base64
import io
import os
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pytest
from PIL import Image
from site_browser import KATEX_DIR, MAKE_TEST, ROOT, PageLog, serve, watch

import glint
from glint.compiler.compose.linking.uniform_params import read_manifest
from glint.compiler.render.images import flip_error
from glint.compiler.target.glslang import validate

if TYPE_CHECKING:
    from playwright.sync_api import Browser, Page

pytestmark = pytest.mark.browser

PICTURES = ("D.ggx", "D.beckmann")  # variant pages with a canvas, two for the D slot's selector
FLIP_LIMIT = 0.01


class LiveSite:
    def __init__(self, url: str, docs: Path, site: Path) -> None:
        self.url = url
        self.docs = docs
        self.site = site  # the built site, served at `url`


@pytest.fixture(scope="module")
def live_site(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LiveSite]:
    """The site built with `site_url` set to where it is served (a folder served before it is
    built, so that the port is known to the build)."""
    pytest.importorskip("material", reason=f"mkdocs-material is not installed: {MAKE_TEST}")
    tmp = tmp_path_factory.mktemp("canvas-site")
    (tmp / "site").mkdir()
    with serve(tmp / "site") as url:
        env = os.environ | {
            "GLINT_SITE_URL": url,
            "GLINT_SITE_DOCS": str(tmp / "docs"),
            "GLINT_SITE_CACHE": str(tmp / "cache"),
            "GLINT_SITE_PICTURES": ",".join(PICTURES),
        }
        if (KATEX_DIR / "katex.min.js").is_file():
            env["GLINT_KATEX_DIR"] = str(KATEX_DIR)
        command = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q"]
        command += ["-f", str(ROOT / "mkdocs.yml"), "-d", str(tmp / "site")]
        result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, result.stderr
        yield LiveSite(url, tmp / "docs", tmp / "site")


def _drawn(page: Page, selector: str = "canvas.glint-live-canvas") -> dict[str, str]:
    """Scroll the canvas into view (it starts lazily) and wait until it drew or failed."""
    canvas = page.locator(selector).first
    canvas.scroll_into_view_if_needed()
    page.wait_for_function(
        """(sel) => { const c = document.querySelector(sel);
           return c && ["drawn", "error"].includes(c.dataset.state); }""",
        arg=selector,
        timeout=60_000,
    )
    state: dict[str, str] = page.evaluate(
        """(sel) => { const c = document.querySelector(sel);
           const pre = c.parentElement.querySelector(".glint-live-errors");
           return {state: c.dataset.state, frames: c.dataset.frames || "0",
                   errors: pre ? pre.textContent : ""}; }""",
        selector,
    )
    assert state["state"] == "drawn", state["errors"]
    return state


def _pixels(page: Page, selector: str = "canvas.glint-live-canvas") -> np.ndarray:
    """The canvas as float RGB in [0, 1], row 0 at the top (what `glint render` gives)."""
    url: str = page.evaluate(f"document.querySelector({selector!r}).toDataURL('image/png')")
    png = base64.b64decode(url.split(",", 1)[1])
    rgb = Image.open(io.BytesIO(png)).convert("RGB")
    return np.asarray(rgb, dtype=np.float32) / 255.0


def _with_defaults(text: str) -> str:
    """The live shader with each uniform parameter back to a #define of its manifest default:
    what the canvas computes before a slider moves."""
    for param in read_manifest(text):
        declaration = f"uniform {param.type} {param.name};"
        value = param.default
        literal = f"vec3({', '.join(map(repr, value))})" if isinstance(value, list) else repr(value)
        text = text.replace(declaration, f"#define {param.name} {literal}")
    return text


def _flip_against_glint(live_site: LiveSite, shader: str, seen: np.ndarray) -> float:
    """Mean FLIP of the canvas's pixels against `glint render` of its shader (a path under the
    docs folder) at the manifest's defaults, at the canvas's size and time."""
    text = (live_site.docs / shader).read_text()
    height, width = seen.shape[:2]
    reference = glint.render(_with_defaults(text), size=(width, height), time=1.0)
    error = flip_error(reference.pixels, seen)
    print(f"{shader}: {width}x{height}, mean FLIP {error:.5f}")
    return error


def _no_problems(log: PageLog) -> None:
    assert log.console_errors == [] and log.page_errors == [], log.problems()


@pytest.mark.parametrize(("page_path", "shader"), [("", "default"), ("catalog/D.ggx/", "D.ggx")])
def test_canvas_draws_what_glint_renders(
    live_site: LiveSite, browser_page: tuple[Page, PageLog], page_path: str, shader: str
) -> None:
    page, log = browser_page
    page.goto(live_site.url + page_path)
    _drawn(page)
    seen = _pixels(page)
    assert seen.mean() > 0.05, "the canvas is black"
    assert _flip_against_glint(live_site, f"img/live/{shader}.glsl", seen) < FLIP_LIMIT
    _no_problems(log)


def test_a_parameter_slider_changes_the_picture(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(live_site.url + "catalog/D.ggx/")
    state = _drawn(page)
    before = _pixels(page)
    names = page.eval_on_selector_all("input[data-param]", "els => els.map(e => e.dataset.param)")
    assert "CAMERA_FOCAL" in names
    slider = "input[data-param='CAMERA_FOCAL']"
    typed = page.locator(slider).locator("xpath=following-sibling::input[@type='number']")
    default = float(typed.input_value())

    def frames_after(count: int) -> None:
        page.wait_for_function(
            "n => Number(document.querySelector('canvas.glint-live-canvas').dataset.frames) > n",
            arg=count,
        )

    # the value typed in: the slider follows it, the picture changes
    frames = int(state["frames"])
    typed.fill(str(default / 2))
    typed.press("Enter")
    frames_after(frames)
    after = _pixels(page)
    assert np.abs(after - before).mean() > 0.01, "the typed value did not change the picture"
    # CAMERA_FOCAL spans three decades (0.1 to 100): the slider is on a log scale, so half the
    # value moves it by log(2) / log(1000) of its travel, not by 1.5 / 99.9
    assert page.get_attribute(slider, "data-scale") == "log"
    moved = int(page.input_value(slider))
    expected = round(1000 * np.log(default / 0.1) / np.log(1000))
    assert abs(expected - moved - 1000 * np.log(2) / np.log(1000)) <= 2
    # the slider itself, dragged to its middle: the value shown is the log-scale midpoint
    page.eval_on_selector(
        slider, "el => { el.value = '500'; el.dispatchEvent(new Event('input')); }"
    )
    assert abs(float(typed.input_value()) - np.sqrt(0.1 * 100)) < 0.01
    # reset: the first value again, and the first picture
    frames = int(page.get_attribute("canvas.glint-live-canvas", "data-frames") or "0")
    page.locator(slider).locator("xpath=following-sibling::button").click()
    frames_after(frames)
    assert float(typed.input_value()) == default
    assert np.abs(_pixels(page) - before).mean() < 1e-3
    _no_problems(log)


def test_material_and_light_controls_change_the_picture_as_they_should(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    """Exposure brightens; a material's roughness changes its sphere's highlights, its albedo
    its colour; a higher dielectric F0 brightens the dielectrics' reflections; the key light
    turned below the horizon darkens the picture (the D slot's roughness-sweep preview)."""
    page, log = browser_page
    page.goto(live_site.url + "catalog/D.ggx/")
    _drawn(page)
    names = page.eval_on_selector_all("input[data-param]", "els => els.map(e => e.dataset.param)")
    assert {"EXPOSURE", "SUN_INTENSITY", "MAT_DIELECTRIC0_ROUGHNESS"} <= set(names)

    def typed(name: str, value: float) -> np.ndarray:
        frames = int(page.get_attribute("canvas.glint-live-canvas", "data-frames") or "0")
        field = page.locator(f"input[data-param='{name}']").locator(
            "xpath=following-sibling::input[@type='number']"
        )
        field.fill(str(value))
        field.press("Enter")
        page.wait_for_function(
            "n => Number(document.querySelector('canvas.glint-live-canvas').dataset.frames) > n",
            arg=frames,
        )
        return _pixels(page)

    before = _pixels(page)
    brighter = typed("EXPOSURE", 4.0)
    assert brighter.mean() > before.mean() + 0.03
    typed("EXPOSURE", 1.0)
    rough = typed("MAT_DIELECTRIC0_ROUGHNESS", 0.9)  # the near-mirror sphere turned rough
    changed = np.abs(rough - before).max(axis=-1) > 3 / 255
    assert 0.002 < changed.mean() < 0.2  # that one sphere, not the whole picture
    typed("MAT_DIELECTRIC0_ROUGHNESS", 0.05)

    def redrawn(action: Callable[[], None]) -> np.ndarray:
        frames = int(page.get_attribute("canvas.glint-live-canvas", "data-frames") or "0")
        action()
        page.wait_for_function(
            "n => Number(document.querySelector('canvas.glint-live-canvas').dataset.frames) > n",
            arg=frames,
        )
        return _pixels(page)

    # the albedo by its colour picker (sRGB): the sphere it colours turns blue, nothing else
    before = _pixels(page)
    blue = redrawn(
        lambda: page.locator("input[data-param='MAT_DIELECTRIC2_ALBEDO']").fill("#0000ff")
    )
    changed = np.abs(blue - before).max(axis=-1) > 3 / 255
    assert 0.002 < changed.mean() < 0.2
    bluer = (blue[..., 2] - blue[..., 0]) - (before[..., 2] - before[..., 0])
    assert bluer[changed].mean() > 0.1
    # F0 from 0.04 to 0.17 (diamond): the dielectrics (the upper row) reflect more, the metals
    # (their F0 is their albedo) do not change
    shiny = typed("DIELECTRIC_F0", 0.17)
    changed = np.abs(shiny - blue).max(axis=-1) > 3 / 255
    half = changed.shape[0] // 2
    assert changed[:half].mean() > 0.02 and changed[half:].mean() < changed[:half].mean() / 5
    assert (shiny - blue)[changed].mean() > 0.02
    typed("DIELECTRIC_F0", 0.04)
    # the key light's elevation: lit from above, the spheres are brighter at their tops; lit
    # from below, at their bottoms (rows count down the picture)
    elevation = "input[data-param='SUN_DIR'][data-component='elevation']"
    assert page.locator(elevation).count() == 1

    def lit_at(degrees: int) -> np.ndarray:
        script = f"el => {{ el.value = '{degrees}'; el.dispatchEvent(new Event('input')); }}"
        return redrawn(lambda: page.eval_on_selector(elevation, script)).mean(axis=-1)

    difference = lit_at(85) - lit_at(-85)
    rows = np.arange(difference.shape[0])[:, None]
    above, below = np.clip(difference, 0, None), np.clip(-difference, 0, None)
    assert above.sum() > 1 and below.sum() > 1
    centre_above = (above * rows).sum() / above.sum()
    centre_below = (below * rows).sum() / below.sum()
    assert centre_above < centre_below - 5, (centre_above, centre_below)
    _no_problems(log)


def test_instant_navigation_starts_the_next_pages_canvas(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(live_site.url)
    _drawn(page)
    assert page.evaluate("window.glintLive.contexts()") == 1
    # A click on a link of the site: Material's instant navigation fetches the page and swaps
    # it in, with no load (the flag set on this window survives). The home page links to no
    # variant page, so the test adds the link a reader would follow.
    page.evaluate(
        """url => { window.glintNoReload = true;
           const link = document.createElement("a");
           link.href = url; link.textContent = "D.ggx";
           document.querySelector("article").appendChild(link);
           link.click(); }""",
        live_site.url + "catalog/D.ggx/",
    )
    # no "load" event under instant navigation: wait for the address and the new content
    page.wait_for_function("location.pathname.endsWith('/catalog/D.ggx/')")
    page.wait_for_selector("canvas.glint-live-canvas[data-shader$='D.ggx.glsl']")
    _drawn(page)
    assert page.evaluate("window.glintNoReload") is True, "the page was loaded again, not swapped"
    # the home page's canvas gave its context back; only this page's is alive
    assert page.evaluate("window.glintLive.contexts()") == 1
    _no_problems(log)


def test_every_example_scene_runs_live_in_the_gallery(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    from glint.compiler.scene.model import load_scene
    from glint.compiler.site.scene_pages import example_scenes

    page, log = browser_page
    page.goto(live_site.url + "gallery/")
    for scene in example_scenes():
        # the first tab of each scene's tier switch is shown: its canvas runs
        selector = f'canvas[data-shader="img/live/scene-{scene.stem}-fast.glsl"]'
        if load_scene(scene).is_mesh:  # rasterized programs: a picture and no canvas
            assert page.locator(selector).count() == 0, scene.stem
            continue
        _drawn(page, selector)
        assert _pixels(page, selector).mean() > 0.05, f"{scene.stem}: the canvas is black"
    _no_problems(log)


def test_a_scenes_picture_is_bound_on_its_live_canvas(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    """The studio's tiled floor (a picture on channel 0): its canvas loads the picture the live
    shader's manifest names and draws what glint renders with that picture bound, not the
    black floor of an unbound channel."""
    import json

    page, log = browser_page
    page.goto(live_site.url + "gallery/")
    shader = "img/live/scene-studio-fast.glsl"
    selector = f'canvas[data-shader="{shader}"]'
    _drawn(page, selector)
    page.wait_for_function(
        "(sel) => document.querySelector(sel).dataset.pictures === '1'", arg=selector,
        timeout=60_000,
    )  # fmt: skip
    seen = _pixels(page, selector)
    text = (live_site.docs / shader).read_text()
    manifest = text[text.index("/* glint-channels\n") + 18 :]
    picture = live_site.docs / json.loads(manifest[: manifest.index("*/")])["0"]
    height, width = seen.shape[:2]
    source = _with_defaults(text)
    bound = glint.render(source, size=(width, height), time=1.0, channels={0: picture})
    black = glint.render(source, size=(width, height), time=1.0)
    error = flip_error(bound.pixels, seen)
    print(f"{shader}: mean FLIP {error:.5f} against glint with the picture bound")
    assert error < FLIP_LIMIT
    assert flip_error(black.pixels, seen) > 2 * error
    _no_problems(log)


def test_a_slot_pages_selector_swaps_the_variant_on_its_canvas(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(live_site.url + "catalog/slots/D/")
    _drawn(page)
    chosen = "img/live/D.beckmann.glsl"
    assert page.get_attribute("canvas.glint-live-canvas", "data-shader") != chosen
    page.select_option("select.glint-live-choice", chosen)
    page.wait_for_function(
        """(path) => { const c = document.querySelector("canvas.glint-live-canvas");
           return c.dataset.shader === path && c.dataset.state === "drawn"; }""",
        arg=chosen,
        timeout=60_000,
    )
    assert _flip_against_glint(live_site, chosen, _pixels(page)) < FLIP_LIMIT
    # the new shader's parameters got sliders, and only one set of them
    live = page.locator(".glint-live").first  # the Live section's (the comparison has two)
    assert live.locator(".glint-live-controls .glint-live-play").count() == 1
    sliders = live.locator(".glint-live-controls .glint-live-slider").count()
    assert sliders == live.locator(".glint-live-controls .glint-live-reset").count() >= 2
    _no_problems(log)


def test_the_ab_split_shows_both_variants_and_their_difference(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    """The slot page's comparison: left of the divider is A's picture, right of it B's (each
    as glint renders it), the divider moves the split, and the difference view is bright
    where A and B differ and dark where they agree."""
    page, log = browser_page
    page.goto(live_site.url + "catalog/slots/D/")
    a_sel, b_sel = ".glint-compare-a-view canvas", ".glint-compare-b-view canvas"
    page.locator(".glint-compare").scroll_into_view_if_needed()
    for selector in (a_sel, b_sel):
        page.wait_for_function(
            "s => document.querySelector(s).dataset.state === 'drawn'", arg=selector,
            timeout=60_000,
        )  # fmt: skip
    a_shader = page.get_attribute(a_sel, "data-shader")
    b_shader = page.get_attribute(b_sel, "data-shader")
    assert a_shader != b_shader
    a, b = _pixels(page, a_sel), _pixels(page, b_sel)
    assert _flip_against_glint(live_site, a_shader or "", a) < FLIP_LIMIT
    assert _flip_against_glint(live_site, b_shader or "", b) < FLIP_LIMIT
    differ = np.abs(a - b).max(axis=-1) > 3 / 255
    assert differ.mean() > 0.01, "the two variants draw the same picture"

    def shown() -> np.ndarray:
        """What the reader sees of the stage: a screenshot of it, scaled to the canvases."""
        png = page.locator(a_sel).screenshot()  # B's canvas lies over A's: both show
        image = Image.open(io.BytesIO(png)).convert("RGB").resize(a.shape[1::-1])
        return np.asarray(image, dtype=np.float32) / 255.0

    for percent in (50, 20):
        page.eval_on_selector(
            ".glint-compare-divider",
            f"el => {{ el.value = '{percent}'; el.dispatchEvent(new Event('input')); }}",
        )
        seen = shown()
        cut = a.shape[1] * percent // 100
        left, right = slice(2, cut - 2), slice(cut + 2, -2)
        assert np.abs(seen[:, left] - a[:, left]).mean() < np.abs(seen[:, left] - b[:, left]).mean()
        assert (
            np.abs(seen[:, right] - b[:, right]).mean()
            < np.abs(seen[:, right] - a[:, right]).mean()
        )
    page.check(".glint-compare-show-difference")
    page.wait_for_function(
        "document.querySelector('.glint-compare-difference').dataset.state === 'drawn'"
    )
    amplified = _pixels(page, ".glint-compare-difference").max(axis=-1)
    assert amplified[differ].mean() > 0.2 and amplified[~differ].mean() < 0.05
    _no_problems(log)


def test_a_compile_error_shows_under_the_canvas_at_the_users_line(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    broken = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n    c = nowhere;\n}\n"
    page.route("**/img/live/D.ggx.glsl", lambda route: route.fulfill(body=broken))
    page.goto(live_site.url + "catalog/D.ggx/")
    page.locator("canvas.glint-live-canvas").scroll_into_view_if_needed()
    page.wait_for_function(
        "document.querySelector('canvas.glint-live-canvas').dataset.state === 'error'",
        timeout=60_000,
    )
    shown = page.text_content(".glint-live-errors") or ""
    assert "nowhere" in shown and ":3:" in shown, shown  # line 3 of the Image-tab code
    assert page.is_visible(".glint-live-errors")
    _no_problems(log)


def test_the_tiers_page_runs_a_tier_when_its_tab_is_opened(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(live_site.url + "tiers/")
    # the reference tier's tab is not the first: its canvas waits, hidden, until it is opened
    selector = 'canvas[data-shader="img/live/scene-default-reference.glsl"]'
    assert page.eval_on_selector(selector, "c => c.dataset.state || ''") == ""
    page.locator(".tabbed-labels label", has_text="reference").first.click()
    _drawn(page, selector)
    assert _pixels(page, selector).mean() > 0.05, "the reference tier's canvas is black"
    _no_problems(log)


def test_a_drag_orbits_the_camera_and_play_runs_the_clock(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(live_site.url)
    state = _drawn(page)
    before = _pixels(page)
    box = page.locator("canvas.glint-live-canvas").bounding_box()
    assert box is not None
    x, y = box["x"] + box["width"] * 0.8, box["y"] + box["height"] * 0.3
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x - box["width"] * 0.3, y + 5, steps=4)
    page.mouse.up()
    page.wait_for_function(
        f"Number(document.querySelector('canvas.glint-live-canvas').dataset.frames) > "
        f"{int(state['frames']) + 2}"
    )
    dragged = _pixels(page)
    assert np.abs(dragged - before).mean() > 0.01, "the drag did not move the camera"
    # Play: frames keep coming and the time slider moves on its own
    time_before = float(page.input_value(".glint-live-slider input"))
    page.click(".glint-live-play")
    frames = int(page.get_attribute("canvas.glint-live-canvas", "data-frames") or "0")
    page.wait_for_function(
        f"Number(document.querySelector('canvas.glint-live-canvas').dataset.frames) > {frames + 3}",
        timeout=60_000,
    )
    page.click(".glint-live-play")  # pause
    assert float(page.input_value(".glint-live-slider input")) != time_before
    _no_problems(log)


def test_many_canvases_keep_within_the_context_budget_and_come_back(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    """A page of more canvases than Chrome keeps contexts for (the tiers page had over 16):
    scrolled through, no more than the script's budget stay alive besides those in view; one
    scrolled back to draws again; one whose context is taken comes back when seen."""
    page, _ = browser_page
    folder = live_site.site / "img" / "live-many"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "ramp.glsl").write_text(
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    c = vec4(p.x / iResolution.x, 0.6, 0.3, 1.0);\n}\n",
        encoding="utf-8",
    )
    count = 22
    canvases = "".join(
        f'<div class="glint-live" id="live{i}"><canvas class="glint-live-canvas" width="64" '
        'height="36" data-shader="img/live-many/ramp.glsl"></canvas></div>'
        for i in range(count)
    )
    page.goto(live_site.url)
    page.set_content(
        "<!doctype html><html><head><meta charset='utf-8'><style>"
        ".glint-live{height:700px}.glint-live canvas{width:64px!important}</style></head><body>"
        + canvases
        + f'<script src="{live_site.url}assets/live-canvas.js"></script></body></html>'
    )
    budget = page.evaluate("window.glintLive.budget")
    assert count > 16 > budget
    most = 0
    for i in range(count):
        _drawn(page, f"#live{i} canvas")
        most = max(most, page.evaluate("window.glintLive.contexts()"))
    assert most <= budget + 2, most  # the budget, plus the one or two in view
    parked = page.evaluate(
        """() => [...document.querySelectorAll("canvas.glint-live-canvas")]
           .filter(c => c.dataset.state === "lost").map(c => c.style.backgroundImage)"""
    )
    assert len(parked) >= count - budget - 2 and all(s.startswith('url("data:') for s in parked)
    # the first canvas, parked long ago, draws again when scrolled back to
    _drawn(page, "#live0 canvas")
    assert _pixels(page, "#live0 canvas").mean() > 0.2
    # a context taken away (as a GPU reset or the browser's own limit does) comes back too
    page.evaluate("document.querySelector('#live0 canvas').glintLive.lose.loseContext()")
    page.wait_for_function("document.querySelector('#live0 canvas').dataset.state === 'lost'")
    page.locator("#live5 canvas").scroll_into_view_if_needed()
    _drawn(page, "#live0 canvas")
    assert _pixels(page, "#live0 canvas").mean() > 0.2
    assert page.evaluate("window.glintLive.contexts()") <= budget + 2


COVERAGE_BATCH = 12  # canvases per page: Chrome keeps about 16 WebGL contexts alive


def _every_variant_live_shader() -> dict[str, str]:
    """Each variant's live shader as a full build makes it (the composition of its picture,
    for webgl2 with parameters as uniforms), composed without rendering."""
    from glint.compiler.catalog.loader import load_catalog
    from glint.compiler.site.pictures import Picture, picture_composition

    shaders = {}
    for snippet in load_catalog().snippets.values():
        composed = picture_composition(snippet.slot, snippet.variant)
        if not isinstance(composed, Picture):  # a Picture says why there is none
            shaders[snippet.id] = composed[0].retarget("webgl2", params_as_uniforms=True).text
    return shaders


def test_every_variants_live_canvas_compiles_and_draws(
    live_site: LiveSite, browser_page: tuple[Page, PageLog]
) -> None:
    """The full coverage pass: every variant's live shader, run by the site's own script on
    small canvases, a batch per page, compiles and draws a picture that is not black."""
    page, _ = browser_page
    shaders = _every_variant_live_shader()
    assert len(shaders) > 50
    folder = live_site.site / "img" / "live-all"
    folder.mkdir(parents=True, exist_ok=True)
    ids = sorted(shaders)
    bad = {}
    for start in range(0, len(ids), COVERAGE_BATCH):
        batch = ids[start : start + COVERAGE_BATCH]
        canvases = []
        for snippet_id in batch:
            (folder / f"{snippet_id}.glsl").write_text(shaders[snippet_id], encoding="utf-8")
            canvases.append(
                f'<div class="glint-live"><canvas class="glint-live-canvas" width="64" '
                f'height="36" data-shader="img/live-all/{snippet_id}.glsl" data-time="1">'
                "</canvas></div>"
            )
        # A page of its own, shown at the site's root (the script finds the shaders from
        # its own URL); the site's pages are not touched.
        page.goto(live_site.url)
        page.set_content(
            "<!doctype html><html><head><meta charset='utf-8'>"
            # small canvases side by side, all in view at once: each starts when it is seen
            "<style>.glint-live{display:inline-block;width:72px;vertical-align:top}"
            ".glint-live canvas{width:64px!important}.glint-live-controls{display:none}"
            "</style></head><body>"
            + "".join(canvases)
            + f'<script src="{live_site.url}assets/live-canvas.js"></script></body></html>'
        )
        page.wait_for_function(
            """() => [...document.querySelectorAll("canvas.glint-live-canvas")]
               .every(c => ["drawn", "error"].includes(c.dataset.state))""",
            timeout=90_000,
        )
        seen = page.evaluate(
            """() => [...document.querySelectorAll("canvas.glint-live-canvas")].map(c => {
                 const pre = c.parentElement.querySelector(".glint-live-errors");
                 const flat = document.createElement("canvas");
                 flat.width = c.width; flat.height = c.height;
                 const ctx = flat.getContext("2d");
                 ctx.drawImage(c, 0, 0);
                 const px = ctx.getImageData(0, 0, c.width, c.height).data;
                 let sum = 0;
                 for (let i = 0; i < px.length; i += 4) sum += px[i] + px[i + 1] + px[i + 2];
                 return {state: c.dataset.state, errors: pre ? pre.textContent : "",
                         mean: sum / (px.length / 4 * 3 * 255)};
               })"""
        )
        for snippet_id, got in zip(batch, seen, strict=True):
            if got["state"] != "drawn" or got["mean"] < 0.02:
                bad[snippet_id] = got
    # Console messages are not checked here: Material's script of the page this harness
    # replaces complains about the page it finds; the real pages are checked above.
    assert not bad, bad


EDITOR_BUNDLE = ROOT / "build" / "editor" / "glint-editor.js"


def _edit_line(page: Page, has_text: str, replacement: str) -> None:
    """Put the cursor on the editor's line that holds `has_text` and type `replacement` over
    the whole line, as a reader would."""
    line = page.locator(".glint-edit .cm-line", has_text=has_text).first
    line.click()
    page.keyboard.press("End")
    page.keyboard.press("Shift+Home")
    page.keyboard.press("Shift+Home")  # the first Home stops at the indentation
    page.keyboard.type(replacement)


def _edit_state(page: Page, state: str) -> str:
    """Wait until the editor's last compile ended in `state`; its status line."""
    page.wait_for_function(
        "(s) => document.querySelector('.glint-edit').dataset.state === s",
        arg=state,
        timeout=60_000,
    )
    return page.text_content(".glint-edit-status") or ""


def test_an_edit_recompiles_the_canvas_and_an_error_shows_at_its_line(
    live_site: LiveSite, browser: Browser
) -> None:
    """A variant page's code in CodeMirror: an edit of D.ggx that makes D zero takes the
    highlights out of the canvas; an undeclared name shows at the edited line of the editor;
    Reset brings the picture back; "Copy as ShaderToy" copies a shader that glslang accepts
    and that holds the edit."""
    if not EDITOR_BUNDLE.is_file():
        pytest.fail(f"the editor's bundle {EDITOR_BUNDLE} is missing: run `make editor`")
    context = browser.new_context(viewport={"width": 1200, "height": 800})
    context.grant_permissions(["clipboard-read", "clipboard-write"])
    page = context.new_page()
    log = watch(page)
    try:
        page.goto(live_site.url + "catalog/D.ggx/")
        _drawn(page)
        page.wait_for_function(
            "document.querySelector('.glint-edit').dataset.state === 'ready'", timeout=60_000
        )
        before = _pixels(page)

        _edit_line(page, "return a2 / (PI * d * d);", "return 0.0;")
        assert _edit_state(page, "compiled") == "compiled"
        _drawn(page)
        flat = _pixels(page)
        # no specular lobe left: the spheres' highlights go, the picture darkens
        assert flat.mean() < before.mean() - 0.01, (flat.mean(), before.mean())

        _edit_line(page, "return 0.0;", "return nowhere;")
        status = _edit_state(page, "error")
        code = (ROOT / "snippets" / "D" / "ggx.glsl").read_text().split("--- */\n", 1)[1]
        expected = next(
            number for number, text in enumerate(code.splitlines(), start=1) if "return a2" in text
        )
        assert status.startswith(f"error at line {expected}:") and "nowhere" in status, status
        assert page.locator(".glint-edit .cm-lint-marker-error").count() == 1

        page.click(".glint-edit-reset")
        assert _edit_state(page, "compiled") == "compiled"
        _drawn(page)
        assert np.abs(_pixels(page) - before).max() <= 1 / 255

        _edit_line(page, "return a2 / (PI * d * d);", "return 0.5 * a2 / (PI * d * d);")
        _edit_state(page, "compiled")
        page.click(".glint-edit-copy")
        page.wait_for_function(
            "document.querySelector('.glint-edit-status').textContent.startsWith('copied')",
            timeout=10_000,
        )
        copied: str = page.evaluate("navigator.clipboard.readText()")
        assert "return 0.5 * a2 / (PI * d * d);" in copied
        assert "return a2 / (PI * d * d);" not in copied
        assert "void mainImage" in copied and "#version" not in copied  # ShaderToy's Image tab
        assert validate(copied, "copied.glsl", "shadertoy") == []  # glslangValidator
        _no_problems(log)
    finally:
        context.close()
