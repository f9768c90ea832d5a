"""Everything the docs site writes from a file is text: a scene's or a snippet's name, a file
name, a snippet's front matter (summary, sources, parameters, formula), a bench label. Each
page is rendered here through the Markdown extensions of mkdocs.yml, as mkdocs renders it, and
no value may become HTML, a link to another scheme than http(s), an attribute or markup."""

from __future__ import annotations

import dataclasses
import html
import re
from html.parser import HTMLParser
from pathlib import Path, PurePosixPath
from typing import Any

import pytest

import glint
from glint.compiler.catalog.loader import parse_snippet
from glint.compiler.markdown import (
    html_attr,
    html_text,
    is_safe_url,
    math_block,
    md_code,
    md_prose,
    md_text,
    safe_image,
    safe_link,
    table,
)
from glint.compiler.site.catalog_pages import (
    VariantDoc,
    index_page,
    slot_docs,
    slot_page,
    variant_page,
)
from glint.compiler.site.live_canvas import LIVE_DIR
from glint.compiler.site.measured import Accuracy, Bench, accuracy_section
from glint.compiler.site.pictures import Picture
from glint.compiler.site.scene_pages import gallery_page, tiers_page
from glint.compiler.site.slot_comparison import slot_comparisons

ROOT = Path(__file__).resolve().parents[2]
NEEDS_MKDOCS = "mkdocs is not installed: pip install -e '.[dev]' (make test and make site do)"

IMG = "<img src=x onerror=alert(1)>"
LINK = "[x](javascript:alert(1))"
ATTRS = "{onclick=alert(1)}"  # attr_list would make it an attribute of a heading
HOSTILE = [
    IMG,
    LINK,
    f"x {ATTRS}",
    "![x](javascript:alert(1))",
    "<javascript:alert(1)>",
    "`<img src=x onerror=alert(1)>`",
    "a\n\n<div onclick=alert(1)>b</div>\n\nc",
    "$x$ \\(y\\) \\[z\\]",
    "*em* _em_ __strong__ **strong**",
    "# heading",
    "- item",
    "1. item",
    '=== "tab"',
    "!!! note",
    "| cell |",
    "&lt;img src=x onerror=alert(1)&gt; &amp;",
    "back\\slash \\` \\*",
]
ORDINARY = [
    "GGX / Trowbridge-Reitz normal distribution",
    "eight_models",
    "Walter et al. 2007, eq. 33",
    "n = 2/a² − 2 (Blinn 1977)",
    'lighting-model skill, step 9 ("can reduce to 3 at far distances")',
]


@pytest.fixture(scope="module")
def render() -> Any:
    """Markdown to HTML as the site renders it: the extensions and settings of mkdocs.yml."""
    pytest.importorskip("mkdocs", reason=NEEDS_MKDOCS)
    pytest.importorskip("pymdownx", reason=NEEDS_MKDOCS)
    import markdown
    from mkdocs.config import load_config

    config = load_config(str(ROOT / "mkdocs.yml"))

    def convert(text: str) -> str:
        return markdown.markdown(
            text,
            extensions=config.markdown_extensions,
            extension_configs=config.mdx_configs,
        )

    return convert


class _Page(HTMLParser):
    """The tags, attributes and text of an HTML page."""

    def __init__(self, page: str) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict[str, str]]] = []
        self.text: list[str] = []
        self.feed(page)
        self.close()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, {name: value or "" for name, value in attrs}))

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def _assert_inert(page: str, images: tuple[str, ...] = ()) -> _Page:
    """No event handler (onerror, onclick, ...: those words only as text), no script, no link
    or image to another scheme than http(s), and no image but those of `images` (their src, in
    the order of the page)."""
    parsed = _Page(page)
    assert not re.search(r"(?i)(href|src)\s*=\s*[\"']?\s*(javascript|data|vbscript):", page)
    for tag, attrs in parsed.tags:
        assert tag not in ("script", "iframe", "object", "embed", "svg", "style"), tag
        assert not any(name.startswith("on") for name in attrs), (tag, attrs)
        for name in ("href", "src", "data-shader", "value"):
            if name in attrs:
                assert is_safe_url(attrs[name]), (tag, attrs)
    assert tuple(attrs["src"] for tag, attrs in parsed.tags if tag == "img") == images
    if not images:
        assert "<img" not in page
    return parsed


def _words(parsed: _Page) -> str:
    return " ".join("".join(parsed.text).split())


# --- the escape functions ------------------------------------------------------------------


@pytest.mark.parametrize("value", HOSTILE)
def test_md_text_shows_exactly_its_text(render: Any, value: str) -> None:
    page = render(f"Before {md_text(value)} after.")
    parsed = _assert_inert(page)
    assert [tag for tag, _ in parsed.tags] == ["p"]  # no markup at all: one paragraph
    assert _words(parsed) == " ".join(f"Before {value} after.".split())


@pytest.mark.parametrize("value", HOSTILE)
@pytest.mark.parametrize(
    "place",
    [
        "# {}\n",
        "### {} {{ #anchor }}\n",
        "- {}\n",
        "{}\n",
        "| a | b |\n|---|---|\n| {} | c |\n",
        "![{}](img/x.png)\n",
        "[{}](page.md)\n",
        '=== "{}"\n\n    text\n',
    ],
)
def test_md_text_is_text_wherever_a_page_puts_it(render: Any, value: str, place: str) -> None:
    """In a heading, a list, a table cell, a link's or an image's text, a tab's title: the
    page has the same elements as with a plain word there, and the value shows as written."""
    page = render(place.format(md_text(value)))
    images = ("img/x.png",) if place.startswith("![") else ()
    parsed = _assert_inert(page, images)
    plain = _Page(render(place.format("plain")))
    assert [tag for tag, _ in parsed.tags] == [tag for tag, _ in plain.tags]
    if place.startswith("### "):
        assert parsed.tags[0][1]["id"] == "anchor"  # the page's own attribute list still works
    shown = _words(parsed)
    if images:
        shown = next(attrs["alt"] for tag, attrs in parsed.tags if tag == "img")
    assert " ".join(value.split()) in " ".join(shown.split())


@pytest.mark.parametrize("value", ORDINARY)
def test_ordinary_text_is_left_alone(value: str) -> None:
    assert md_text(value) == value
    assert md_prose(value) == value
    assert md_code(value) == f"`{value}`"
    assert html_text(value) == html.escape(value, quote=False)


@pytest.mark.parametrize(
    "value",
    [
        "a`b",
        "`",
        "``",
        "a ``` b",
        "`<img src=x onerror=alert(1)>`",
        "#!python print(1)",
        ":::js alert(1)",
        "x | y",
        "a\nb",
        " ",
        "<b>&amp;</b>",
        "\\",
    ],
)
def test_md_code_holds_any_value(render: Any, value: str) -> None:
    page = render(f"| a | b |\n|---|---|\n| {md_code(value)} | c |\n")
    parsed = _assert_inert(page)
    codes = [tag for tag, _ in parsed.tags if tag == "code"]
    assert codes == ["code"]
    shown = re.search(r"<code>(.*?)</code>", page, re.S)
    assert shown is not None
    assert html.unescape(shown.group(1)) == value.replace("\n", " ").strip()


def test_md_prose_keeps_code_spans_and_nothing_else(render: Any) -> None:
    value = f"Whether it casts shadows (the `shadow` slot), e.g. {LINK} `a``b` {IMG} `x"
    page = render(md_prose(value))
    parsed = _assert_inert(page)
    assert re.findall(r"<code>(.*?)</code>", page) == ["shadow", "a``b"]
    assert _words(parsed) == value.replace("`shadow`", "shadow").replace("`a``b`", "a``b")


@pytest.mark.parametrize(
    "url",
    [
        "javascript:alert(1)",
        "JaVaScRiPt:alert(1)",
        " javascript:alert(1)",
        "java\tscript:x",
        "java\nscript:x",
        "&#106;avascript:alert(1)",
        "data:text/html,<script>alert(1)</script>",
        "vbscript:msgbox(1)",
        "file:///etc/passwd",
        "x:y",
    ],
)
def test_links_to_other_schemes_are_text(render: Any, url: str) -> None:
    assert not is_safe_url(url)
    assert safe_link("label", url) == "label"
    assert safe_image("label", url) == "label"
    parsed = _assert_inert(render(f"See {safe_link(md_text('label'), url)}."))
    assert _words(parsed) == "See label."


@pytest.mark.parametrize(
    "url, href",
    [
        ("https://example.org/a?b=1&c=2#d", "https://example.org/a?b=1&amp;c=2#d"),
        ("http://example.org", "http://example.org"),
        ("../D.ggx.md", "../D.ggx.md"),
        ("#anchor", "#anchor"),
        ("img/a b(1).png", "img/a%20b%281%29.png"),
    ],
)
def test_http_and_relative_links_stay_links(render: Any, url: str, href: str) -> None:
    page = render(safe_link("label", url))
    assert f'href="{href}"' in page


def test_raw_html_values_are_escaped() -> None:
    assert html_attr('a"b<c>&\n\nd') == "a&quot;b&lt;c&gt;&amp;&#10;&#10;d"
    assert html_text("<b>\n\n</b>") == "&lt;b&gt;&#10;&#10;&lt;/b&gt;"


@pytest.mark.parametrize(
    "latex",
    ["x $$\n<div onclick=alert(1)>x</div>\n$$", f"a\n\n{IMG}\n\nb", "\\frac{a}{b} < c & d"],
)
def test_a_formula_stays_math(render: Any, latex: str) -> None:
    page = render(f"## Formula\n\n{math_block(latex)}\nAfter.\n")
    _assert_inert(page)
    math = re.search(r'<div class="arithmatex">(.*?)</div>', page, re.S)
    assert math is not None
    assert html.unescape(math.group(1)).split() == ["\\[", *latex.split(), "\\]"]


def test_a_formula_renders_as_arithmatex_renders_it(render: Any) -> None:
    """The real formulas come out as they would through `$$` (arithmatex's own block), with
    side-by-side definitions one a line (math_block)."""
    from glint.compiler.markdown import _one_definition_a_line

    formulas = [s.formula for s in glint.catalog().values() if s.formula]
    assert formulas
    for latex in formulas:
        lines = _one_definition_a_line(latex.strip())
        assert render(math_block(latex)) == render(f"$$\n{lines}\n$$\n")


def test_the_real_catalog_reads_as_before(render: Any) -> None:
    """Every summary and source of the real catalog shows the same text as before the
    escaping (when it went in as HTML-escaped Markdown), and the scene model's descriptions
    keep their code spans."""
    from glint.compiler.scene.model import Scene

    catalog = glint.catalog().values()
    values = [s.summary for s in catalog] + [source for s in catalog for source in s.sources]
    for value in values:
        before = render(html.escape(value, quote=False))
        after = render(md_prose(value))
        assert _words(_Page(after)) == _words(_Page(before)), value
    schema = Scene.model_json_schema()
    for model in [schema, *schema["$defs"].values()]:
        for prop in model.get("properties", {}).values():
            value = " ".join(prop.get("description", "").split())
            before = render(table(["a"], [[html.escape(value, quote=False).replace("|", "\\|")]]))
            after = render(table(["a"], [[md_prose(value)]]))
            assert after == before or _words(_Page(after)) == _words(_Page(before)), value
            assert after.count("<code>") == before.count("<code>"), value


# --- the pages, from a hostile catalog and hostile scenes -----------------------------------


def _hostile_snippet(tmp_path: Path) -> VariantDoc:
    """A snippet file of the catalog's form whose name and front matter are hostile, read by
    the catalog's own loader."""
    stem = f"evil{IMG}"
    text = (
        "/* ---\n"
        f'id = "D.{stem}"\n'
        'slot = "D"\n'
        f'summary = "{LINK} {IMG} {ATTRS} `code` *em*"\n'
        'provides = ["distribution"]\n'
        "requires = []\n"
        f'sources = ["{LINK}", "{IMG}", "[y](data:text/html,x)"]\n'
        "formula = '''x $$\n<div onclick=alert(1)>x</div>\n\n" + IMG + "\n$$'''\n"
        'params = { EVIL = { type = "float", default = 1.0 } }\n'
        "--- */\n"
        "float distribution(float NoH, float a) { return 1.0; }\n"
    )
    path = tmp_path / "snippets" / "D" / f"{stem}.glsl"
    path.parent.mkdir(parents=True)
    path.write_text(text, encoding="utf-8")
    snippet = parse_snippet(text, f"snippets/D/{path.name}")
    return VariantDoc(
        id=snippet.id,
        slot=snippet.slot,
        summary=snippet.summary,
        file=snippet.file,
        source=snippet.body,
        standalone=snippet.body,
        provides=snippet.provides,
        requires=(f"PI`{IMG}`",),
        params=dict(snippet.params),
        sources=snippet.sources,
        formula=snippet.formula,
        tiers=(f"fast {IMG}",),
    )


def test_catalog_pages_of_a_hostile_snippet_are_text(tmp_path: Path, render: Any) -> None:
    doc = _hostile_snippet(tmp_path)
    scheme = VariantDoc(id="javascript:alert(1)//", slot="D", summary=LINK, file="x", source="",
                        standalone="")  # fmt: skip
    scene_file = f"snippets/scenes/x`{IMG}`{ATTRS}.toml"
    picture = Picture(
        path=PurePosixPath("img/variants") / f"{doc.id}.png",
        scene_file=scene_file,
        shader="void mainImage() {}",
        live="void main() {}",
    )
    no_picture = Picture(scene_file=scene_file, note=f"No picture: {picture.scene} fails.")
    pages = {
        "variant": variant_page(doc, picture),
        "no picture": variant_page(doc, no_picture),
        "scheme": variant_page(scheme),
        "index": index_page([doc, scheme], slot_docs([doc, scheme]), {doc.id: picture}),
        "slot": slot_page(slot_docs([doc, scheme])[0]),
    }
    image = "../img/variants/D.evil%3Cimg%20src%3Dx%20onerror%3Dalert%281%29%3E.png"
    for name, markdown in pages.items():
        images = (image,) if name in ("variant", "index") else ()
        parsed = _assert_inert(render(markdown), images)
        words = _words(parsed)
        if name != "scheme":
            assert doc.id in words, name  # the hostile name, as text
        if name in ("variant", "no picture"):
            assert f"{LINK} {IMG} {ATTRS} code *em*." in words  # the summary, as written
            assert LINK in words and "[y](data:text/html,x)" in words  # the sources
            assert f"PI`{IMG}`" in words and scene_file in words
        if name == "scheme":
            assert "javascript:alert(1)//" in words
    assert 'href="javascript%3Aalert%281%29%2F%2F.md"' in render(pages["index"])


def _hostile_scenes(tmp_path: Path) -> list[Path]:
    """Example scenes whose file names are hostile: one with its own GLSL in a file whose name
    holds backticks, one mesh scene."""
    source = ROOT / "snippets" / "scenes"
    folder = tmp_path / "scenes"
    folder.mkdir()
    geometry = f"isl`and`{IMG}``.glsl"
    (folder / geometry).write_text((source / "island.glsl").read_text(encoding="utf-8"))
    island = (source / "island.toml").read_text(encoding="utf-8")
    assert 'file = "island.glsl"' in island
    scene = folder / f"{IMG} {ATTRS}.toml"
    scene.write_text(island.replace('file = "island.glsl"', f'file = "{geometry}"'))
    mesh = folder / f"mesh{IMG}.toml"
    mesh.write_text((source / "eight_models.toml").read_text(encoding="utf-8"))
    return [scene, mesh]


def test_scene_pages_of_hostile_scenes_are_text(tmp_path: Path, render: Any) -> None:
    scene, mesh = _hostile_scenes(tmp_path)
    stem = scene.stem
    renders = {(stem, tier): PurePosixPath(f"img/scenes/{stem}-{tier}.png")
               for tier in ("fast", "balanced", "reference")}  # fmt: skip
    large = {stem: PurePosixPath(f"img/scenes/{stem}-large.png")}
    live_tiers = {(stem, tier): LIVE_DIR / f"scene-{stem}-{tier}.glsl"
                  for tier in ("fast", "balanced", "reference")}  # fmt: skip
    meshes = {mesh.stem: PurePosixPath(f"img/scenes/{mesh.stem}.png")}
    gallery = gallery_page(large, live_tiers, meshes, [scene, mesh])
    encoded = "%3Cimg%20src%3Dx%20onerror%3Dalert%281%29%3E"
    parsed = _assert_inert(
        render(gallery),
        (
            f"img/scenes/{encoded}%20%7Bonclick%3Dalert%281%29%7D-large.png",
            f"img/scenes/mesh{encoded}.png",
        ),
    )
    words = _words(parsed)
    assert stem in words and mesh.stem in words  # the hostile names, as text
    assert f"glint render snippets/scenes/{scene.name}" in words
    assert f"isl`and`{IMG}``.glsl, the scene's own distance function" in words
    headings = [t for t, _ in parsed.tags if t == "h2"]
    assert len(headings) == 2
    tiers = tiers_page(renders, {}, {}, live_tiers, [scene, mesh])
    parsed = _assert_inert(
        render(tiers),
        tuple(
            f"img/scenes/{encoded}%20%7Bonclick%3Dalert%281%29%7D-{tier}.png"
            for tier in ("fast", "balanced", "reference")
        ),
    )
    assert stem in _words(parsed) and mesh.stem in _words(parsed)


def test_bench_labels_are_text(render: Any) -> None:
    row = {"id": f"D.{IMG}", "reference": f"`{IMG}`", "error_unit": LINK, "max_abs": 0.5,
           "rms": 0.1, "max_rel": None, "worst_at": {IMG: 0.25}, "samples": IMG, "spirv": LINK,
           "gpu_ns": 1.5, "pareto": False}  # fmt: skip
    bench = Bench(machine=f"{IMG} {LINK}", variants={row["id"]: row})
    section = slot_comparisons({"D": [row["id"]]}, {}, {}, bench, None).sections["D"]
    accuracy = accuracy_section(row["id"], Accuracy(row), bench.machine)
    for markdown in (section, accuracy):
        words = _words(_assert_inert(render(markdown)))
        assert f"{IMG} {LINK}" in words and LINK in words


def test_the_bench_report_is_text(render: Any) -> None:
    """bench.md, which the site shows as its Benchmark page: a scene, a variant, a slot and a
    machine named with markup stay text."""
    from glint.compiler.bench.report import BenchResult, to_markdown
    from glint.compiler.bench.scenes import Goal, TierMeasure
    from glint.compiler.bench.variants import VariantMeasure

    fields = {f.name for f in dataclasses.fields(VariantMeasure)}
    variant = VariantMeasure(**{name: None for name in fields} | {
        "id": f"D.{IMG}", "slot": LINK, "reference": IMG, "spirv": 3, "pareto": True})  # fmt: skip
    tier = TierMeasure(scene=IMG, tier=LINK, frame_ms=1.0, flip=0.0, time_vs_reference=1.0,
                       spirv=10)  # fmt: skip
    goal = Goal(name=IMG, target=LINK, reached=True, measured=IMG)
    result = BenchResult({"renderer": IMG, "platform": LINK, "cpu": True}, [variant], [tier],
                         [goal])  # fmt: skip
    words = _words(_assert_inert(render(to_markdown(result))))
    assert IMG in words and LINK in words


def test_side_by_side_definitions_become_one_line_each() -> None:
    from glint.compiler.markdown import math_block

    block = math_block(r"F = F_0 + (1 - F_0)\,x^5, \quad x = 1 - \cos\theta")
    assert (
        "\\begin{gathered}\nF = F_0 + (1 - F_0)\\,x^5 \\\\\nx = 1 - \\cos\\theta\n\\end{gathered}"
        in block
    )
    # only at the top level: not inside a brace group, a \left...\right pair or an environment
    for kept in (r"\text{a}_{b \quad c} = 1", r"\left( a \quad b \right)",
                 r"\begin{cases} a \quad b \end{cases}", r"a \qquad b"):  # fmt: skip
        assert "gathered" not in math_block(kept), kept
