"""The catalog's pages: an index of every variant, one page per slot, one page per variant.

Everything on them comes from the catalog itself (the snippet files, `slots.py`, `tiers.toml`),
so a new variant gets its page by existing; nothing is written by hand per variant. The page
text is made by pure functions of plain data (`VariantDoc`, `SlotDoc`), so that a test can feed
them a made-up snippet, for instance one whose comments hold `</script>`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from typing import Any

import glint
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.catalog.tiers import TIERS, tier_choice, tier_table
from glint.compiler.markdown import (
    fenced,
    math_block,
    md_code,
    md_prose,
    md_text,
    path_url,
    safe_image,
    safe_link,
    table,
    url_part,
)

from .live_canvas import live_section
from .measured import Accuracy, accuracy_section, time_per_call
from .pictures import SIZE, TIME, Picture
from .source_links import source_link

CATALOG_DIR = PurePosixPath("catalog")


@dataclass(frozen=True)
class VariantDoc:
    """What the page of one variant shows."""

    id: str
    slot: str
    summary: str
    file: str  # e.g. "snippets/D/ggx.glsl"
    source: str  # the GLSL body
    standalone: str  # what `glint catalog show ID` prints
    provides: tuple[str, ...] = ()
    requires: tuple[str, ...] = ()
    params: dict[str, object] = field(default_factory=dict)
    sources: tuple[str, ...] = ()
    formula: str = ""  # LaTeX, from the front matter's `formula`
    tiers: tuple[str, ...] = ()  # how the tiers use it, one phrase each


@dataclass(frozen=True)
class SlotDoc:
    """What the page of one slot shows: its contract and its variants."""

    name: str
    summary: str
    entry: str | None
    prototype: str | None
    many: bool
    variants: tuple[tuple[str, str], ...]  # (id, summary)


def variant_path(snippet_id: str) -> PurePosixPath:
    return CATALOG_DIR / f"{snippet_id}.md"


def slot_path(slot: str) -> PurePosixPath:
    return CATALOG_DIR / "slots" / f"{slot}.md"


def catalog_pages(
    variants: list[VariantDoc] | None = None,
    pictures: Mapping[str, Picture] | None = None,
    accuracy: Mapping[str, Accuracy] | None = None,
    machine: str = "",
    slot_sections: Mapping[str, str] | None = None,
) -> dict[PurePosixPath, str]:
    """Every catalog page, by its path under the docs folder; a variant in `pictures` shows
    its picture (or why it has none), one in `accuracy` what is measured of it (on `machine`);
    a slot's page ends with its section in `slot_sections` (its variants compared)."""
    variants = variant_docs() if variants is None else variants
    pictures = pictures or {}
    accuracy = accuracy or {}
    slot_sections = slot_sections or {}
    slots = slot_docs(variants)
    pages = {CATALOG_DIR / "index.md": index_page(variants, slots, pictures, accuracy)}
    pages |= {slot_path(slot.name): _joined(slot_page(slot), slot_sections.get(slot.name, ""))
              for slot in slots}  # fmt: skip
    pages |= {
        variant_path(doc.id): variant_page(doc, pictures.get(doc.id), accuracy.get(doc.id), machine)
        for doc in variants
    }
    return pages


def variant_docs() -> list[VariantDoc]:
    """The catalog as `VariantDoc`s, in the order of `glint catalog`."""
    table_ = tier_table()
    docs = []
    for snippet in glint.catalog().values():
        docs.append(
            VariantDoc(
                id=snippet.id,
                slot=snippet.slot,
                summary=snippet.summary,
                file=snippet.file,
                source=snippet.source,
                standalone=snippet.standalone(),
                provides=snippet.provides,
                requires=snippet.requires,
                params=dict(snippet.params),
                sources=snippet.sources,
                formula=snippet.formula,
                tiers=tuple(tier_uses(snippet.slot, snippet.variant, table_)),
            )
        )
    return docs


def slot_docs(variants: Iterable[VariantDoc]) -> list[SlotDoc]:
    """One `SlotDoc` per slot that has variants: the slots of `slots.py` in their order, then
    any other."""
    by_slot: dict[str, list[tuple[str, str]]] = {}
    for doc in variants:
        by_slot.setdefault(doc.slot, []).append((doc.id, doc.summary))
    names = [name for name in SLOTS if name in by_slot]
    names += sorted(name for name in by_slot if name not in SLOTS)
    docs = []
    for name in names:
        slot = SLOTS.get(name)
        docs.append(
            SlotDoc(
                name=name,
                summary=slot.summary if slot else "",
                entry=slot.entry if slot else None,
                prototype=slot.prototype if slot else None,
                many=slot.many if slot else False,
                variants=tuple(by_slot[name]),
            )
        )
    return docs


def tier_uses(slot: str, variant: str, tiers: dict[str, dict[str, str]]) -> list[str]:
    """How the tiers of `tiers.toml` use `slot.variant`: a tier's own choice falls back on
    balanced's, as the planner's does; rough-diffuse materials take `[rough_diffuse]`."""
    uses = []
    for tier in TIERS:
        if tier_choice(tiers, tier, slot) == variant:
            uses.append(tier)
    if slot == "diffuse":
        rough = tiers.get("rough_diffuse", {})
        uses += [f"{tier} (rough materials)" for tier in TIERS if rough.get(tier) == variant]
    return uses


def index_page(
    variants: list[VariantDoc],
    slots: list[SlotDoc],
    pictures: Mapping[str, Picture] | None = None,
    accuracy: Mapping[str, Accuracy] | None = None,
) -> str:
    """The catalog index: one row per variant, with its picture and what the bench measured
    where known. catalog-cards.js turns the table into cards with filters; without JavaScript
    the table is the page."""
    pictures = pictures or {}
    accuracy = accuracy or {}
    rows = []
    for doc in variants:
        measured = accuracy[doc.id].measured if doc.id in accuracy else None
        measured = measured or {}
        rows.append(
            [
                _variant_link(doc.id, ""),
                _slot_link(doc.slot, ""),
                md_prose(doc.summary),
                "★" if measured.get("pareto") else "",
                _error(measured),
                time_per_call(measured["gpu_ns"], unit=False) if "gpu_ns" in measured else "",
                _thumbnail(doc.id, pictures.get(doc.id)),
            ]
        )
    slot_links = ", ".join(_slot_link(slot.name, "") for slot in slots)
    header = ["id", "slot", "summary", "front", "RMS error", "ns per call", "picture"]
    return (
        "# Catalog\n\n"
        f"{len(variants)} variants in {len(slots)} slots, generated from the snippet files "
        "(`glint catalog` lists the same). Every variant of a slot defines the slot's entry "
        "function with the same prototype, so any one replaces any other. ★ marks a variant "
        "on its slot's cost/error front; the RMS error is against the variant's float64 "
        "reference, as a share of the reference's own RMS where values differ in scale "
        "between variants, else in its unit (degrees, visibility); the time is per call, "
        "both from `glint bench` "
        "([Benchmark](../bench/bench.md)).\n\n"
        f"Slots: {slot_links}.\n\n"
        '<div id="glint-catalog-filter" hidden></div>\n\n' + table(header, rows)
    )


def slot_page(slot: SlotDoc) -> str:
    """A slot's contract and its variants."""
    parts = [f"# Slot {md_code(slot.name)}\n\n"]
    if slot.summary:
        summary = md_prose(slot.summary)
        parts.append(f"{summary[:1].upper()}{summary[1:]}.\n\n")  # keeps "SDF" as it is
    parts.append("## Contract\n\n")
    if slot.many:
        parts.append(
            "A library slot: a scene takes as many of its snippets as it needs, each "
            "providing its own functions.\n\n"
        )
    if slot.entry and slot.prototype:
        parts.append(
            f"Every variant defines the entry function {md_code(slot.entry)} with exactly this "
            "prototype, so that any variant replaces any other:\n\n"
        )
        parts.append(fenced(slot.prototype + ";", "glsl") + "\n")
    elif not slot.many:
        parts.append("No entry function: the scene's own code calls what the variant provides.\n\n")
    parts.append("## Variants\n\n")
    rows = [[_variant_link(id_, "../"), md_prose(summary)] for id_, summary in slot.variants]
    parts.append(table(["variant", "summary"], rows))
    return "".join(parts)


def _joined(*sections: str) -> str:
    """Markdown sections one after another, a blank line between: a heading right under a table's
    last row would be read as one more row of it."""
    return "\n".join(s.rstrip("\n") + "\n" for s in sections if s)


# A variant's own page comes first among the results of a search for its name (Material's
# search boost, in the page's front matter): "ggx" finds D.ggx before pages that mention it.
SEARCH_FIRST = "---\nsearch:\n  boost: 4\n---\n\n"


def variant_page(
    doc: VariantDoc,
    picture: Picture | None = None,
    accuracy: Accuracy | None = None,
    machine: str = "",
) -> str:
    """One variant: summary, picture, formula, accuracy and cost, code in tabs, contract,
    tiers, sources."""
    slot = _slot_link(doc.slot, "")
    parts = [
        SEARCH_FIRST,
        f"# {md_code(doc.id)}\n\n",
        f"{md_prose(doc.summary)}. Slot {slot}; file {md_code(doc.file)}.\n\n",
    ]
    if picture is not None:
        parts += ["## Picture\n\n", picture_block(doc, picture), "\n"]
    parts.append(live_section(doc.id, picture))  # the picture's shader, live (live_canvas.py)
    if doc.formula:
        parts += ["## Formula\n\n", math_block(doc.formula), "\n"]
    parts.append(accuracy_section(doc.id, accuracy, machine))
    parts += [
        "## Code\n\n",
        '=== "Snippet"\n\n',
        fenced(doc.source, "glsl", indent="    "),
        "\n",
        f'=== "{md_code("glint catalog show")}"\n\n',
        "    The snippet with everything it needs (other slots at their balanced-tier "
        "variants), as one block to paste:\n\n",
        fenced(doc.standalone, "glsl", indent="    ", searchable=False),
        "\n",
    ]
    if picture is not None and picture.shader:
        parts += [
            f'=== "{_scene_tab(picture)}"\n\n',
            f"    What `glint compose` writes for {picture.scene} with this variant, to paste "
            "into ShaderToy's Image tab: the shader of the picture above.\n\n",
            fenced(picture.shader, "glsl", indent="    ", searchable=False),
            "\n",
        ]
    parts += [
        "## Contract\n\n",
        f"- provides: {_codes(doc.provides)}\n",
        f"- requires: {_codes(doc.requires)}\n",
    ]
    if doc.params:
        params = ", ".join(md_code(f"{name} = {value}") for name, value in doc.params.items())
        parts.append(f"- parameters (`#define`, defaults): {params}\n")
    parts += ["\n## Tiers\n\n", _tiers(doc), "\n"]
    if doc.sources:
        parts += ["## Sources\n\n", *(f"- {_source(source)}\n" for source in doc.sources)]
    return "".join(parts)


def _source(source: str) -> str:
    """A source as the page lists it: linked to the paper or page where one is known."""
    url = source_link(source)
    return safe_link(md_prose(source), url) if url else md_prose(source)


def _scene_tab(picture: Picture) -> str:
    """The tab's title: the scene the variant is composed into."""
    if picture.own_scene:
        return "Its scene"
    if picture.scene_file is None:
        return "The default scene with it"
    return md_text(f"{PurePosixPath(picture.scene_file).stem} scene with it")


def _variant_link(snippet_id: str, up: str) -> str:
    """A link to a variant's page from a page `up` ("", "../") below the catalog folder."""
    return safe_link(md_code(snippet_id), f"{up}{url_part(snippet_id)}.md")


def _error(measured: Mapping[str, Any]) -> str:
    """A variant's RMS error as the index compares it across slots: relative to its reference's
    RMS where it has one (values of any scale), else with its unit (degrees, visibility)."""
    relative = measured.get("rel_rms")
    if relative is not None:
        # two significant digits either way: 0.55 %, or 7.8e-08 where a percentage reads 0.00 %
        return f"{100 * relative:.2g} %" if relative >= 1e-3 else f"{relative:.1e} (relative)"
    if measured.get("rms") is None:
        return ""
    unit = measured.get("error_unit") or ""
    return f"{measured['rms']:.3g}" + ("°" if unit == "degrees" else f" {md_text(unit)}")


def _slot_link(slot: str, up: str) -> str:
    return safe_link(md_code(slot), f"{up}slots/{url_part(slot)}.md")


def _codes(names: Iterable[str]) -> str:
    return ", ".join(md_code(name) for name in names) or "nothing"


def _tiers(doc: VariantDoc) -> str:
    if doc.tiers:
        return f"Used by the tiers: {md_text(', '.join(doc.tiers))}.\n"
    command = md_code(f"glint compose --variant {doc.slot}={doc.id.split('.', 1)[-1]}")
    return (
        f"No tier picks it by default: take it with {command} or a scene's "
        "`[quality.variants]`, or the scene's content picks it.\n"
    )


def _alt(snippet_id: str, picture: Picture) -> str:
    return md_text(f"{picture.scene_text} rendered with {snippet_id}")


def _thumbnail(snippet_id: str, picture: Picture | None) -> str:
    if picture is None or picture.path is None:
        return ""
    return safe_image(_alt(snippet_id, picture), path_url(picture.path, "../")) + '{ width="96" }'


def picture_block(doc: VariantDoc, picture: Picture) -> str:
    """The picture and the scene it shows, or the line that says why there is none."""
    if picture.path is None:
        return f"{picture.note}\n"  # Markdown, escaped where pictures.py makes it
    variant = doc.id.split(".", 1)[-1]
    image = safe_image(_alt(doc.id, picture), path_url(picture.path, "../"))
    if picture.own_scene:  # a library snippet: its scene's shader is in the tab below
        return (
            f"{image}\n\nglint's render of {picture.scene}, which takes it "
            f"({SIZE[0]}x{SIZE[1]} pixels, time {TIME:g}).\n"
        )
    scene = f" {picture.scene_file}" if picture.scene_file else ""
    command = md_code(f"glint compose{scene} --variant {doc.slot}={variant}")
    return (
        f"{image}\n\n"
        f"glint's render of {picture.scene} composed with {command} "
        f"({SIZE[0]}x{SIZE[1]} pixels, time {TIME:g}).\n"
    )
