"""The docs site builds with `mkdocs build --strict`, covers the catalog, the lint rules and the
commands, loads nothing from the network, never lets shader text become HTML, and shows each
variant's picture, rendered once."""

from __future__ import annotations

import html
import json
import os
import re
import subprocess
import sys
from pathlib import Path, PurePosixPath

import pytest

import glint
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.cli import build_parser
from glint.compiler.errors import UsageError
from glint.compiler.render.images import png_pixels
from glint.compiler.site import build_docs
from glint.compiler.site.catalog_pages import VariantDoc, catalog_pages, slot_path, variant_page
from glint.compiler.site.cli_reference import commands
from glint.compiler.site.katex_assets import KATEX_DIR
from glint.compiler.site.measured import Accuracy, accuracy_section
from glint.compiler.site.pictures import selection_from_env, variant_pictures

ROOT = Path(__file__).resolve().parents[2]
NEEDS_MKDOCS = "mkdocs is not installed: pip install -e '.[dev]' (make test and make site do)"


def _katex_dir(tmp: Path) -> Path:
    """Debian's KaTeX where libjs-katex is installed (make site), else a stand-in with the same
    files: CI installs only what `make test` needs, and the test checks references, not
    typesetting."""
    if (KATEX_DIR / "katex.min.js").is_file():
        return KATEX_DIR
    stand_in = tmp / "katex"
    for name in ("katex.min.js", "katex.min.css", "contrib/auto-render.js"):
        (stand_in / name).parent.mkdir(parents=True, exist_ok=True)
        (stand_in / name).write_text("/* stand-in for libjs-katex */\n")
    (stand_in / "fonts").mkdir()
    (stand_in / "fonts" / "KaTeX_Main-Regular.woff2").write_bytes(b"stand-in")
    return stand_in


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    pytest.importorskip("mkdocs", reason=NEEDS_MKDOCS)
    pytest.importorskip("material", reason=NEEDS_MKDOCS)
    tmp = tmp_path_factory.mktemp("site")
    env = os.environ | {
        "GLINT_SITE_DOCS": str(tmp / "docs"),
        "GLINT_KATEX_DIR": str(_katex_dir(tmp)),
        # the whole site's pictures take ~10 s on llvmpipe: test_variant_pictures renders a few
        "GLINT_SITE_CACHE": str(tmp / "cache"),
        "GLINT_SITE_PICTURES": "none",
    }
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q"]
    command += ["-f", str(ROOT / "mkdocs.yml"), "-d", str(tmp / "site")]
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    return tmp / "site"


def _page(site: Path, path: str) -> str:
    return (site / path / "index.html").read_text(encoding="utf-8")


def test_every_catalog_id_has_a_page_linked_from_the_index(site: Path) -> None:
    index = _page(site, "catalog")
    for snippet_id in glint.catalog():
        assert (site / "catalog" / snippet_id / "index.html").is_file(), snippet_id
        assert f'href="{snippet_id}/"' in index, snippet_id


def test_every_slot_page_states_its_contract(site: Path) -> None:
    from glint.compiler.catalog.slots import SLOTS

    for snippet in glint.catalog().values():
        page = _page(site, f"catalog/slots/{snippet.slot}")
        assert f'href="../../{snippet.id}/"' in page
        prototype = SLOTS[snippet.slot].prototype
        if prototype:
            assert html.escape(prototype.split("(")[0].split()[-1]) in page


def test_a_formula_is_math_for_katex(site: Path) -> None:
    page = _page(site, "catalog/D.ggx")
    assert '<div class="arithmatex">' in page and r"\frac{\alpha^2}" in page
    assert "Used by the tiers: fast, balanced, reference" in page


def test_every_lint_rule_has_an_anchor(site: Path) -> None:
    from glint.lint.rules import all_rules

    page = _page(site, "rules")
    for code in all_rules():
        assert f'id="{code.lower()}"' in page, code


def test_every_command_has_its_help(site: Path) -> None:
    page = _page(site, "cli")
    for name, _ in commands(build_parser()):
        assert f"<code>{name}</code>" in page, name


def test_getting_started_has_the_commands_picture_and_api(site: Path) -> None:
    page = _page(site, "")
    words = re.sub(r"<[^>]+>", "", page)  # Pygments splits code into spans
    assert "make demo" in words and "make test" in words and "glint.compose(" in words
    assert 'src="examples/default.png"' in page
    assert (site / "examples" / "default.png").is_file()


_SOURCES = re.compile(r"<(?:script|img)\b[^>]*\bsrc=\"([^\"]*)\"|<link\b[^>]*\bhref=\"([^\"]*)\"")


def test_nothing_is_loaded_from_the_network(site: Path) -> None:
    pages = list(site.rglob("*.html"))
    assert len(pages) > len(glint.catalog())
    for page in pages:
        for match in _SOURCES.finditer(page.read_text(encoding="utf-8")):
            url = match.group(1) or match.group(2)
            assert not re.match(r"(https?:)?//", url), f"{page}: {url}"
    for sheet in site.rglob("*.css"):
        assert not re.search(r"(@import|url\()\s*['\"]?(https?:)?//", sheet.read_text()), sheet
    katex = _page(site, "catalog/D.ggx")
    for asset in ("katex.min.js", "contrib/auto-render.js", "katex-init.js", "katex.min.css"):
        assert f"../../assets/katex/{asset}" in katex
        assert (site / "assets" / "katex" / asset).is_file()
    assert list((site / "assets" / "katex" / "fonts").glob("KaTeX_*"))


def test_shader_text_stays_text() -> None:
    markdown = pytest.importorskip("markdown", reason=NEEDS_MKDOCS)
    pytest.importorskip("pymdownx", reason=NEEDS_MKDOCS)
    hostile = "// </script><script>alert(1)</script> & <b>\n// ```\nvoid f() {}\n"
    doc = VariantDoc(
        id="D.hostile",
        slot="D",
        summary="a <script> in the summary",
        file="snippets/D/hostile.glsl",
        source=hostile,
        standalone=hostile,
        sources=("<img src=x onerror=alert(1)>",),
    )
    page = markdown.markdown(
        variant_page(doc),
        extensions=["tables", "pymdownx.highlight", "pymdownx.superfences", "pymdownx.tabbed"],
        extension_configs={"pymdownx.tabbed": {"alternate_style": True}},
    )
    assert "<script" not in page and "<img" not in page and "<b>" not in page
    assert page.count("&lt;/script&gt;") == 4  # two per code block, both tabs
    assert page.count("void") == 2  # the ``` in a comment did not close the fence


def test_rebuilding_rewrites_nothing_and_prunes_what_is_gone(tmp_path: Path) -> None:
    """`mkdocs serve` rebuilds when the docs folder changes: a rebuild that changes nothing
    must write nothing, or it would rebuild forever."""
    katex = _katex_dir(tmp_path)
    docs = tmp_path / "docs"
    build_docs(ROOT / "site" / "docs", docs, ROOT / "README.md", katex)
    stale = docs / "catalog" / "D.removed.md"
    stale.write_text("# gone\n")
    times = {path: path.stat().st_mtime_ns for path in docs.rglob("*") if path.is_file()}
    build_docs(ROOT / "site" / "docs", docs, ROOT / "README.md", katex)
    assert not stale.exists()
    assert all(path.stat().st_mtime_ns == t for path, t in times.items() if path != stale)


def test_generated_pages_never_land_in_the_sources(tmp_path: Path) -> None:
    with pytest.raises(UsageError):
        build_docs(ROOT / "site" / "docs", ROOT / "site" / "docs" / "gen", ROOT / "README.md")
    (tmp_path / "mine.txt").write_text("not the docs build's")
    with pytest.raises(UsageError, match="not made by glint"):
        build_docs(ROOT / "site" / "docs", tmp_path, ROOT / "README.md", _katex_dir(tmp_path))
    assert (tmp_path / "mine.txt").is_file()


# one from a slot the default scene fills, one it does not (lamp.toml's point light), a library
PICTURED = ("D.beckmann", "D.ggx", "attenuation.quadratic")
LIBRARY = "core.constants"


@pytest.mark.render
def test_variant_pictures_are_shown_and_rendered_once(tmp_path: Path) -> None:
    Image = pytest.importorskip("PIL.Image")
    numpy = pytest.importorskip("numpy")
    docs, cache = tmp_path / "docs", tmp_path / "cache"
    chosen = (*PICTURED, LIBRARY)
    build_docs(
        ROOT / "site" / "docs", docs, ROOT / "README.md", _katex_dir(tmp_path), cache, chosen
    )
    index = (docs / "catalog" / "index.md").read_text()
    for snippet_id in PICTURED:
        png = docs / "img" / "variants" / f"{snippet_id}.png"
        with Image.open(png) as image:
            assert image.size == (192, 108)
            assert numpy.asarray(image.convert("RGB")).mean() / 255 > 0.02, snippet_id
        image_with_alt = re.compile(
            rf"!\[[^\]]+\]\(\.\./img/variants/{re.escape(snippet_id)}\.png\)"
        )
        assert image_with_alt.search(index), snippet_id
        assert image_with_alt.search((docs / "catalog" / f"{snippet_id}.md").read_text())
    lamp = (docs / "catalog" / "attenuation.quadratic.md").read_text()
    assert "snippets/scenes/lamp.toml" in lamp
    # the shader of the picture, in its own tab, as `glint compose` writes it
    assert '=== "lamp scene with it"' in lamp
    composed = glint.compose(ROOT / "snippets" / "scenes" / "lamp.toml",
                             variants={"attenuation": "quadratic"}).text  # fmt: skip
    assert "\n".join("    " + line if line else "" for line in composed.splitlines()) in lamp
    library = (docs / "catalog" / f"{LIBRARY}.md").read_text()
    assert "no picture" in library and "img/variants" not in library
    assert sorted(p.name for p in (docs / "img" / "variants").iterdir()) == [
        f"{snippet_id}.png" for snippet_id in sorted(PICTURED)
    ]

    times = {path: path.stat().st_mtime_ns for path in cache.iterdir()}
    renders = [path for path in times if re.fullmatch(r"[0-9a-f]{64}\.png", path.name)]
    assert len(renders) == len(PICTURED)
    assert variant_pictures(chosen, cache).rendered == 0
    build_docs(
        ROOT / "site" / "docs", docs, ROOT / "README.md", _katex_dir(tmp_path), cache, chosen
    )
    assert {path: path.stat().st_mtime_ns for path in cache.iterdir()} == times


def test_a_variant_that_fails_to_compose_has_no_picture_and_breaks_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    compose = glint.compose

    def failing(scene: object = None, **options: object) -> glint.Shader:
        if options.get("variants"):
            raise glint.InputError("made to fail")
        return compose(scene, **options)  # type: ignore[arg-type]

    monkeypatch.setattr(glint, "compose", failing)
    pictures = variant_pictures(["D.beckmann"], tmp_path / "cache")
    assert pictures.rendered == 0 and not pictures.files
    assert "fails to compose" in pictures.by_id["D.beckmann"].note
    assert not (tmp_path / "cache").exists()


def test_which_pictures_the_environment_asks_for() -> None:
    assert selection_from_env(None) is None and selection_from_env("all") is None
    assert selection_from_env("none") == ()
    assert selection_from_env("D.ggx, sss.sdf_probe") == ("D.ggx", "sss.sdf_probe")


def test_variant_and_slot_pages_show_what_is_measured(tmp_path: Path) -> None:
    """The bench's numbers and the budget on a variant's page, its GLSL plotted against its
    reference, its float16 survival; the slot's variants side by side with FLIP images."""
    Image = pytest.importorskip("PIL.Image")
    docs, cache = tmp_path / "docs", tmp_path / "cache"
    build_docs(ROOT / "site" / "docs", docs, ROOT / "README.md", _katex_dir(tmp_path), cache,
               ("D.ggx", "D.beckmann"))  # fmt: skip
    bench = json.loads((ROOT / "site" / "docs" / "bench" / "bench.json").read_text())
    row = next(r for r in bench["variants"] if r["id"] == "D.ggx")
    page = (docs / "catalog" / "D.ggx.md").read_text()
    section = page[page.index("## Accuracy and cost") : page.index("## Code")]
    assert f"| SPIR-V instructions | {row['spirv']} |" in section
    assert f"| RMS error | {row['rms']:.3g} |" in section
    budget = load_catalog().get("D.ggx").error_budget["max_rel"]
    assert f"| {row['max_rel']:.3g} | ≤ {budget:.3g} |" in section
    # GGX's denominator underflows in half precision at the lowest roughness
    assert "does **not** survive float16" in section
    with Image.open(docs / "img" / "accuracy" / "D.ggx.png") as plot:
        assert plot.size[0] > 400 and plot.size[1] > 200
    assert "](../img/accuracy/D.ggx.png)" in section
    slot = (docs / "catalog" / "slots" / "D.md").read_text()
    assert "| [`D.ggx`](../D.ggx.md) |" in slot and "the reference | 0 |" in slot
    beckmann = re.search(
        r"\| \[`D\.beckmann`\][^\n]*img/flip/D\.beckmann\.png[^|]*\| ([0-9.]+) \|", slot
    )
    assert beckmann is not None and 0.0 < float(beckmann.group(1)) < 0.2
    with Image.open(docs / "img" / "flip" / "D.beckmann.png") as flip:
        assert flip.size == (192, 108)
    assert (docs / "img" / "charts" / "D.png").is_file()
    assert "★" in slot  # the front


def test_accuracy_section_from_plain_data() -> None:
    row = {"id": "X.y", "reference": "X_y", "error_unit": "degrees", "max_abs": 0.5, "rms": 0.1,
           "max_rel": None, "worst_at": {"t": 0.25}, "samples": 10, "spirv": 42,
           "gpu_ns": 1.5, "pareto": False}  # fmt: skip
    half_fails = {"float16": {"finite": False, "nonfinite_lanes": 3, "max_rel_err_vs_f64": 9.0},
                  "float32": {"finite": True, "max_rel_err_vs_f64": 1e-7}}  # fmt: skip
    text = accuracy_section("X.y", Accuracy(row, {"max_abs": 1.0}, half_fails), "a test GPU")
    assert "| max error | 0.5 (degrees) | ≤ 1 |" in text
    assert "| worst at | t = 0.25 |" in text
    assert "| on its slot's cost/error front | no |" in text
    assert "3 sample(s) turn infinite or NaN" in text and "a test GPU" in text
    assert accuracy_section("X.y", None, "") == ""
    assert "| time per call | 1.50 ns |" in text
    # a relative RMS beside the absolute one; a budget's reason under the table; a time the
    # bench clamped to 0 is below what the probe resolves, not free
    row |= {"rel_rms": 0.0123, "gpu_ns": 0.0}
    why = "the model's design error"
    text = accuracy_section("X.y", Accuracy(row, {"max_abs": 1.0}, budget_why=why), "")
    assert "| RMS error / the reference's RMS | 0.0123 |" in text
    assert "Why the budget is what it is: the model's design error" in text
    assert "| time per call | ≈ 0, within the timing noise |" in text and "0.00 ns" not in text


def test_scene_reference_has_every_key_and_the_gallery_every_example_scene() -> None:
    from pathlib import PurePosixPath

    from glint.compiler.scene.model import Scene
    from glint.compiler.site.scene_pages import example_scenes, gallery_page, scene_reference_page

    page = scene_reference_page()
    schema = Scene.model_json_schema()
    for model in [schema, *schema["$defs"].values()]:
        for key in model["properties"]:
            assert f"| `{key}` |" in page, key
    for name in schema["$defs"]:
        assert f"{{ #{name.lower()} }}" in page, name
    assert "| `roughness` | number (≥ 0, ≤ 1) | `0.5` |" in page
    assert "[gallery](gallery.md)" in page and "### default" not in page  # no longer buried
    live = {(s.stem, tier): PurePosixPath(f"img/live/scene-{s.stem}-{tier}.glsl")
            for s in example_scenes() for tier in ("fast", "balanced", "reference")}  # fmt: skip
    gallery = gallery_page({"default": PurePosixPath("img/scenes/default-large.png")}, live)
    for scene in example_scenes():
        assert f"## {scene.stem}\n" in gallery
        assert scene.read_text(encoding="utf-8").strip().splitlines()[-1] in gallery
    default = gallery.split("## default\n", 1)[1].split("\n## ", 1)[0]
    assert "img/scenes/default-large.png" in default and "(768x432 pixels" in default
    # the tier switch: one tab per tier, each with the scene live at that tier
    for tier in ("fast", "balanced", "reference"):
        assert f'=== "{tier}"' in default
        assert f'data-shader="img/live/scene-default-{tier}.glsl"' in default
    # the mesh example: its TOML and why it has no live canvas (its picture needs a render)
    mesh = gallery.split("## eight_models\n", 1)[1].split("\n## ", 1)[0]
    assert 'builtin = "icosphere"' in mesh and "glint-live" not in mesh
    assert "no live canvas, which runs ShaderToy shaders" in mesh


def test_tiers_page_pictures_every_tier_with_flip_against_reference(tmp_path: Path) -> None:
    from glint.compiler.catalog.tiers import TIERS
    from glint.compiler.site.channels import PICTURES_DIR
    from glint.compiler.site.scene_pages import example_scenes, scene_pages

    built = scene_pages(ROOT / "site" / "docs", tmp_path, pictured=("default", "eight_models"))
    pictures = sorted(  # the rendered pictures; a scene's own pictures (channels) apart
        p.name for p in built.files if p.suffix == ".png" and PICTURES_DIR not in p.parents
    )
    # the mesh example: one picture, at its own tier (its materials choose their models); the
    # default scene at every tier, and large for the gallery
    expected_pictures = [*(f"default-{t}.png" for t in TIERS), "default-large.png"]
    assert pictures == sorted([*expected_pictures, "eight_models.png"])
    large = png_pixels(built.files[PurePosixPath("img/scenes/default-large.png")])
    assert large.shape == (432, 768, 3) and large.std() > 0.05
    mesh = png_pixels(built.files[PurePosixPath("img/scenes/eight_models.png")])
    assert mesh.std() > 0.05  # the spheres are drawn, not only the sky
    assert (
        "![the eight_models scene](img/scenes/eight_models.png)"
        in built.pages[PurePosixPath("gallery.md")]
    )
    # every raymarched scene runs live as written and at every tier (the tabs of the tiers
    # page and the gallery); the mesh scene does not (it is no ShaderToy shader)
    live = sorted(p.name for p in built.files if p.suffix == ".glsl")
    stems = [scene.stem for scene in example_scenes() if scene.stem != "eight_models"]
    expected = [f"scene-{s}-{t}.glsl" for s in stems for t in TIERS]
    assert live == sorted(expected)
    tiers = built.pages[PurePosixPath("tiers.md")]
    rows = dict(re.findall(r"\| `(\w+)` \| !\[default at \w+\]\([^)]+\) \| ([0-9.]+) \|", tiers))
    assert set(rows) == set(TIERS)
    assert float(rows["reference"]) == 0.0
    assert 0.0 < float(rows["fast"]) < 0.1  # another normal, marcher and AO: not the same pixels
    assert "[`ggx`](catalog/D.ggx.md)" in tiers
    assert (
        "![the default scene](img/scenes/default-large.png)"
        in built.pages[PurePosixPath("gallery.md")]
    )


def test_a_variant_measured_on_samples_is_plotted_as_the_bench_measures_it(
    tmp_path: Path,
) -> None:
    """AO is measured on points of its reference scenes, not a grid of inputs: its page plots
    each sample's GLSL output against the reference, and the worst error it plots is the one
    the bench reported (same samples, same GPU path)."""
    pytest.importorskip("PIL.Image")
    from glint.compiler.site.measured import load_bench, sample_errors, variant_accuracy

    bench = load_bench(ROOT / "site" / "docs")
    built = variant_accuracy(["ao.sdf3"], bench, tmp_path)
    accuracy = built.by_id["ao.sdf3"]
    assert accuracy.plot_kind == "samples" and accuracy.plot in built.files
    section = accuracy_section("ao.sdf3", accuracy, bench.machine)
    assert "Measured on the bench's samples" in section
    measured = sample_errors(load_catalog().get("ao.sdf3"))
    assert measured is not None and measured.value is not None and measured.truth is not None
    row = bench.variants["ao.sdf3"]
    assert len(measured.error) == row["samples"]
    assert float(measured.error.max()) == pytest.approx(row["max_abs"], rel=1e-3, abs=1e-4)
    # a variant whose error comes from a render, not probes, gets no sample plot
    assert sample_errors(load_catalog().get("normal.derivative_flat")) is None


def _headings_glued_to_the_line_above(markdown: str) -> list[str]:
    """Headings (outside fenced code) whose line above is not blank: under a table, Markdown
    reads such a heading as one more row of it."""
    glued, fenced, previous = [], False, ""
    for line in markdown.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced and line.startswith("#") and previous.strip():
            glued.append(line)
        previous = line
    return glued


def test_a_slots_compared_variants_come_under_their_own_heading() -> None:
    # The slot page ends with its table of variants; the comparison section after it used to
    # be read as one more row of that table, its heading lost (14 of 26 slot pages).
    pages = catalog_pages(slot_sections={"D": "## Side by side\n\nEach variant.\n"})
    page = pages[slot_path("D")]
    assert "## Side by side" in page
    assert _headings_glued_to_the_line_above(page) == []
    assert all(_headings_glued_to_the_line_above(text) == [] for text in pages.values())


def test_float16_is_said_to_hold_only_within_its_accuracy() -> None:
    """'Survives float16' was said of variants whose relative error in half reached 6e4: a
    finite but inaccurate result is now called what it is, with its number."""
    from glint.compiler.site.measured import HALF_ACCURATE, _precision_text

    def said(finite: bool, error: float | None) -> str:
        half = {"finite": finite, "max_rel_err_vs_f64": error, "nonfinite_lanes": 3}
        return _precision_text({"float16": half, "float32": {"max_rel_err_vs_f64": 1e-7}})

    assert "holds in float16" in said(True, HALF_ACCURATE / 2)
    inaccurate = said(True, 6.2e4)
    assert "holds" not in inaccurate and "survive" not in inaccurate
    assert "is not accurate: its largest relative error is 6.2e+04" in inaccurate
    assert "does **not** survive float16" in said(False, None)


def test_a_page_says_where_and_why_float16_fails() -> None:
    """D.ggx fails float16 only where its true value (1/(pi a^2) = 8e4 at NoH = 1, a = 0.002)
    is beyond float16's range, so only a clamp survives there; D.beckmann fails across the
    domain in an intermediate step while most of its values fit."""
    from glint.compiler.site.measured import _precision_text
    from glint.compiler.verify.precision import precision_report

    ggx = _precision_text(precision_report("D.ggx"))
    assert "does **not** survive float16" in ggx
    assert "at NoH = 1, a = 0.002" in ggx and "beyond float16's largest finite number" in ggx
    assert "no float16 code can hold it" in ggx and "intermediate" not in ggx
    beckmann = precision_report("D.beckmann")["float16"]
    said = _precision_text({"float16": beckmann})
    others = beckmann["nonfinite_lanes"] - beckmann["nonfinite_beyond_range"]
    assert others > 0 and f"in the other {others} an intermediate step" in said
    assert "holds" not in _precision_text(precision_report("V.cook_torrance"))


def test_a_variants_sources_link_to_the_papers() -> None:
    from glint.compiler.site.catalog_pages import variant_docs

    docs = {doc.id: doc for doc in variant_docs()}
    page = variant_page(docs["D.ggx"])
    sources = page[page.index("## Sources") :]
    assert "[Walter et al. 2007, eq. 33](https://doi.org/10.2312/EGWR/EGSR07/195-206)" in sources
    schlick = variant_page(docs["F.schlick"])
    assert "(https://doi.org/10.1111/1467-8659.1330233)" in schlick
    # a source without a known address stays text
    from glint.compiler.site.source_links import source_link

    doc = next(d for d in docs.values() if any(not source_link(s) for s in d.sources))
    listed = [x for x in variant_page(doc).split("## Sources", 1)[1].splitlines()
              if x.startswith("- ")]  # fmt: skip
    linked = [x for x in listed if "](" in x]
    assert len(listed) == len(doc.sources) > len(linked)
    assert len(linked) == sum(1 for s in doc.sources if source_link(s))


def test_the_catalog_compares_errors_on_one_scale_or_names_the_unit() -> None:
    from glint.compiler.site.catalog_pages import _error

    assert _error({"rms": 11.8, "rel_rms": 0.0062}) == "0.62 %"  # D's 1e4 peaks, relatively
    assert _error({"rms": 1e-4, "rel_rms": 7.8e-8}) == "7.8e-08 (relative)"  # never "0.00 %"
    assert _error({"rms": 0.31, "error_unit": "degrees"}) == "0.31°"
    assert _error({"rms": 0.21, "error_unit": "visibility"}) == "0.21 visibility"
    assert _error({}) == ""
