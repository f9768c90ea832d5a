"""The docs site in a real browser (Debian's Chromium through Playwright): pages load with no
console error and nothing from outside 127.0.0.1, links and pictures resolve, formulas typeset,
every catalog id and lint rule is there, and shader text in a page stays text.

A representative set of pages goes through the browser (each visit costs a page load); every
HTML file gets a cheap pass without it: its internal links, pictures, scripts and anchors.
"""

from __future__ import annotations

import contextlib
import re
import subprocess
import sys
import urllib.error
import urllib.request
from html.parser import HTMLParser
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING, Any
from urllib.parse import urljoin, urlsplit

import pytest
from site_browser import ROOT, BuiltSite, PageLog, serve

import glint

if TYPE_CHECKING:
    from playwright.sync_api import Page

pytestmark = pytest.mark.browser

# The variants visited besides the pictured ones: a formula, a library snippet, slots the
# default scene does not use, a mediump variant.
VARIANTS = (
    "D.ggx",
    "F.schlick",
    "D.beckmann",
    "D.ggx_mediump",
    "V.cook_torrance",
    "F.schlick_f90",
    "core.constants",
    "attenuation.quadratic",
    "sss.sdf_probe",
    "tonemap.aces",
    "env.gradient",
    "shadow.hard",
    "ibl.env_brdf_approx",  # the widest formula: four definitions
)
OTHER_PAGES = ("", "catalog/", "rules/", "cli/", "architecture/", "bench/bench/")

# Run in the page once it has loaded: waits for the pictures, then reports them, the links and
# the formulas (KaTeX typesets on Material's document$, after the load event).
_INSPECT = """async () => {
  await Promise.all([...document.images].map((img) => img.complete ? null :
    new Promise((done) => { img.onload = img.onerror = done; })));
  return {
    images: [...document.images].map((img) => [img.src, img.naturalWidth]),
    links: [...document.querySelectorAll("a[href]")].map((a) => a.href),
    formulas: document.querySelectorAll(".arithmatex").length,
    typeset: [...document.querySelectorAll(".arithmatex")].filter(
      (e) => e.querySelector(".katex")).length,
    // with throwOnError: false, a parse error becomes .katex-error and an unknown macro red text
    katexErrors: document.querySelectorAll(
      '.katex-error, .katex [mathcolor="#cc0000"]').length,
    // display formulas wider than their column: a reader sees them cut at the right edge
    scrolled: [...document.querySelectorAll("div.arithmatex")].filter(
      (e) => e.scrollWidth > e.clientWidth + 1).map((e) => e.textContent.slice(0, 40)),
  };
}"""
_TYPESET = """() => [...document.querySelectorAll(".arithmatex")].every(
  (e) => e.querySelector(".katex"))"""


def _browser_pages(site: BuiltSite) -> list[str]:
    """The pages the browser visits, as paths under the site's URL."""
    catalog = glint.catalog()
    variants = [*VARIANTS, *site.pictures]
    assert set(variants) <= set(catalog), set(variants) - set(catalog)  # a renamed variant
    slots = sorted({snippet.slot for snippet in catalog.values()})
    pages = [*OTHER_PAGES, *(f"catalog/slots/{slot}/" for slot in slots)]
    return pages + [f"catalog/{snippet_id}/" for snippet_id in dict.fromkeys(variants)]


def _visit(page: Page, url: str) -> tuple[dict[str, Any], list[str]]:
    """Load `url` and inspect it; the problems found on the way, one line each."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    problems = []
    response = page.goto(url, wait_until="load")
    if response is None or response.status != 200:
        problems.append(f"{url}: status {response and response.status}")
    with contextlib.suppress(PlaywrightTimeout):  # reported below: formulas left untypeset
        page.wait_for_function(_TYPESET, timeout=10_000)
    found: dict[str, Any] = page.evaluate(_INSPECT)
    if found["typeset"] < found["formulas"]:
        problems.append(f"{url}: {found['formulas'] - found['typeset']} formulas not typeset")
    if found["katexErrors"]:
        problems.append(f"{url}: {found['katexErrors']} KaTeX errors")
    problems += [f"{url}: formula wider than its column: {text}" for text in found["scrolled"]]
    problems += [f"{url}: picture {src} not decoded" for src, width in found["images"] if not width]
    return found, problems


def _status(url: str) -> int:
    try:
        with urllib.request.urlopen(url, timeout=10) as response:
            return response.status
    except urllib.error.HTTPError as error:
        return error.code


def test_pages_load_clean_in_the_browser(
    built_site: BuiltSite, site_url: str, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    problems: list[str] = []
    targets: set[str] = set()
    for path in _browser_pages(built_site):
        found, found_problems = _visit(page, site_url + path)
        problems += found_problems
        targets.update(src for src, _ in found["images"])
        targets.update(link.split("#")[0] for link in found["links"] if link.startswith(site_url))
    problems += log.problems()
    problems += [f"outside request: {url}" for url in log.requests if not _local(url, site_url)]
    problems += [f"broken: {url}" for url in sorted(targets) if _status(url) != 200]
    assert not problems, "\n".join(problems)
    assert log.requests and targets


def _local(url: str, site_url: str) -> bool:
    # data: and blob: URLs are made in the page (Material's icons); nothing leaves the machine
    return url.startswith(site_url) or url.startswith(("data:", "blob:"))


def test_formulas_typeset_and_pictures_show(
    built_site: BuiltSite, site_url: str, browser_page: tuple[Page, PageLog]
) -> None:
    """Where the pictures were rendered, the variant's page shows its own; D.ggx's formula is
    typeset by KaTeX into real math."""
    page, log = browser_page
    for snippet_id in built_site.pictures:
        found, problems = _visit(page, f"{site_url}catalog/{snippet_id}/")
        assert not problems, problems
        shown = [src for src, width in found["images"] if width > 0]
        assert any(src.endswith(f"/img/variants/{snippet_id}.png") for src in shown), snippet_id
    found, problems = _visit(page, f"{site_url}catalog/D.ggx/")
    assert not problems and found["formulas"] and found["typeset"] == found["formulas"]
    assert page.locator(".arithmatex .katex-display .mfrac").count() > 0
    assert not log.problems()


def test_every_lint_rule_has_an_anchor_on_the_rules_page(
    site_url: str, browser_page: tuple[Page, PageLog]
) -> None:
    from glint.lint.rules import all_rules

    page, _ = browser_page
    page.goto(f"{site_url}rules/")
    ids = set(page.evaluate("() => [...document.querySelectorAll('[id]')].map((e) => e.id)"))
    missing = [code for code in all_rules() if code.lower() not in ids]
    assert not missing, f"lint rules with no anchor on the rules page: {missing}"


def test_every_catalog_id_has_a_page_and_its_picture(built_site: BuiltSite) -> None:
    missing = []
    for snippet_id in glint.catalog():
        page = built_site.root / "catalog" / snippet_id / "index.html"
        if not page.is_file():
            missing.append(f"no page: {snippet_id}")
        elif snippet_id in built_site.pictures:
            src = f'src="../../img/variants/{snippet_id}.png"'
            if src not in page.read_text(encoding="utf-8"):
                missing.append(f"no picture on the page: {snippet_id}")
            if not (built_site.root / "img" / "variants" / f"{snippet_id}.png").is_file():
                missing.append(f"no picture file: {snippet_id}")
    assert not missing, "\n".join(missing)
    assert built_site.pictures, "no picture was rendered: the render path is broken"


class _References(HTMLParser):
    """The ids of a page and what it refers to: links, pictures, scripts, style sheets."""

    def __init__(self) -> None:
        super().__init__()
        self.ids: set[str] = set()
        self.refs: list[tuple[str, str]] = []  # (tag, URL)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        if values.get("id"):
            self.ids.add(values["id"] or "")
        name = {"a": "href", "link": "href", "img": "src", "script": "src"}.get(tag)
        if name and values.get(name):
            self.refs.append((tag, values[name] or ""))


def _parse(path: Path) -> _References:
    parser = _References()
    parser.feed(path.read_text(encoding="utf-8"))
    return parser


def test_every_page_links_only_to_what_exists(built_site: BuiltSite) -> None:
    """The pass over every HTML file, without the browser: each internal reference names a file
    of the site, and each #anchor an id of its page."""
    root = built_site.root
    parsed = {page: _parse(root / page) for page in built_site.pages()}
    problems = []
    for page, refs in parsed.items():
        if page.name == "404.html":
            continue  # served at any depth, so its links are absolute to the site's URL
        base = "/" + page.as_posix()
        for tag, ref in refs.refs:
            if re.match(r"[a-z]+:|//", ref):
                # a link may lead out of the site; what the page loads may not
                if tag != "a" and not ref.startswith("data:"):
                    problems.append(f"{page}: loads {ref} from outside")
                continue
            parts = urlsplit(urljoin(base, ref))
            target = PurePosixPath(parts.path.lstrip("/"))
            if parts.path.endswith("/"):
                target = target / "index.html"
            if not (root / target).is_file():
                problems.append(f"{page}: {ref} -> missing {target}")
            elif parts.fragment and target.suffix == ".html":
                ids = parsed[Path(target)].ids if Path(target) in parsed else set()
                if parts.fragment not in ids:
                    problems.append(f"{page}: {ref} -> no #{parts.fragment} in {target}")
    assert not problems, "\n".join(problems)
    assert len(parsed) > len(glint.catalog())


HOSTILE = '</script><img src=x onerror="window.__pwned=1">'


def test_shader_text_stays_text_in_the_browser(
    tmp_path: Path, browser_page: tuple[Page, PageLog]
) -> None:
    """A made-up variant whose comment closes a script and opens an img, rendered by mkdocs with
    the site's own configuration: the browser shows the text and runs nothing."""
    yaml = pytest.importorskip("yaml")
    pytest.importorskip("mkdocs", reason="mkdocs is not installed: run `make test`")
    from mkdocs.utils.yaml import yaml_load

    from glint.compiler.site.catalog_pages import VariantDoc, variant_page

    source = f"// {HOSTILE}\nfloat D(float a) {{ return a; }}\n"
    doc = VariantDoc(
        id="D.hostile",
        slot="D",
        summary="a made-up variant",
        file="snippets/D/hostile.glsl",
        source=source,
        standalone=source,
        sources=(HOSTILE,),
    )
    docs = tmp_path / "docs"
    (docs / "catalog" / "slots").mkdir(parents=True)
    (docs / "index.md").write_text("# escaping\n\n[the variant](catalog/D.hostile.md)\n")
    (docs / "catalog" / "slots" / "D.md").write_text("# D\n")
    (docs / "catalog" / "D.hostile.md").write_text(variant_page(doc))
    # the site's theme and Markdown extensions, without the hook that would regenerate the docs
    with open(ROOT / "mkdocs.yml", encoding="utf-8") as file:
        config = yaml_load(file)  # mkdocs' own loader: the file may use !ENV
    for key in ("hooks", "watch", "nav", "not_in_nav", "extra_javascript", "extra_css", "site_url"):
        config.pop(key, None)
    config |= {"docs_dir": str(docs), "site_dir": str(tmp_path / "site")}
    (tmp_path / "mkdocs.yml").write_text(yaml.safe_dump(config))
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q"]
    result = subprocess.run(
        [*command, "-f", str(tmp_path / "mkdocs.yml")], capture_output=True, text=True, timeout=120
    )
    assert result.returncode == 0, result.stderr

    page, log = browser_page
    with serve(tmp_path / "site") as url:
        page.goto(f"{url}catalog/D.hostile/", wait_until="load")
        assert HOSTILE in page.locator("article").inner_text()
        assert page.evaluate("() => window.__pwned") is None
        assert page.locator("img[onerror]").count() == 0
        assert page.locator("img[src='x']").count() == 0
    assert not log.problems()


def test_search_finds_a_variant_by_its_name_first_and_not_in_composed_shaders(
    built_site: BuiltSite, site_url: str, browser_page: tuple[Page, PageLog]
) -> None:
    """The issue-27 search: composed shaders, which hold every snippet they use, are not
    indexed (they matched every search); a variant's page comes first for its own name."""
    import json

    index = json.loads((built_site.root / "search" / "search_index.json").read_text())
    texts = [doc["text"] for doc in index["docs"]]
    composed = re.compile(r"// glint \S+ - scene '")  # the first line of a composed shader
    assert sum(1 for t in texts if composed.search(t)) == 0
    page, _ = browser_page
    page.goto(site_url)
    first_result = """() => { const a = document.querySelector(".md-search-result__item a");
                              return a ? a.getAttribute("href") : ""; }"""
    expected = (
        ("ggx", "catalog/D.ggx/"),
        ("mediump", "catalog/D.ggx_mediump/"),
        ("schlick", "catalog/F.schlick/"),
    )
    for query, first in expected:
        field = page.locator("input.md-search__input")
        field.fill("")
        field.press_sequentially(query, delay=20)  # typed: Material searches on keystrokes
        # the results are replaced as the worker answers: wait for the expected one on top
        try:
            page.wait_for_function(f"() => ({first_result})().endsWith({first!r})", timeout=20_000)
        except Exception:  # noqa: BLE001 (report what came first instead of a timeout)
            pytest.fail(f"{query!r}: first result {page.evaluate(first_result)!r}, not {first}")


def test_dark_mode_follows_the_system_and_the_toggle(site_url: str, browser: Any) -> None:
    context = browser.new_context(color_scheme="dark", viewport={"width": 1200, "height": 800})
    try:
        page = context.new_page()
        page.goto(site_url + "catalog/")
        scheme = "document.body.getAttribute('data-md-color-scheme')"
        background = "getComputedStyle(document.body).backgroundColor"
        assert page.evaluate(scheme) == "slate"
        dark = page.evaluate(background)
        page.locator("label.md-header__button[title='Light mode']").first.click()
        page.wait_for_function(f"{scheme} === 'default'")
        assert page.evaluate(background) != dark
    finally:
        context.close()


def test_pages_fit_a_phone_screen(built_site: BuiltSite, site_url: str, browser: Any) -> None:
    """At 390 px wide no page scrolls sideways, once its live canvases have drawn and built
    their controls (a slider row with its typed value and reset was wider than a phone)."""
    context = browser.new_context(viewport={"width": 390, "height": 844})
    try:
        page = context.new_page()
        for path in ("", "gallery/", "catalog/D.ggx/", "catalog/slots/D/"):
            page.goto(site_url + path)
            canvas = page.locator("canvas.glint-live-canvas").first
            if canvas.count():
                canvas.scroll_into_view_if_needed()
                page.wait_for_function(
                    "() => ['drawn', 'error'].includes("
                    "document.querySelector('canvas.glint-live-canvas').dataset.state)",
                    timeout=60_000,
                )
            width = page.evaluate("document.documentElement.scrollWidth")
            assert width <= 391, f"/{path} is {width} px wide on a 390 px screen"
    finally:
        context.close()
