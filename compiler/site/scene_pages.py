"""Two pages about scenes as a whole: the scene reference (every key of a scene file, from the
scene model's JSON schema, and every example scene with its TOML and picture) and the tiers
(which variant each tier takes for each slot, and every example scene at every tier with its
FLIP error against the reference tier and its frame time from the bench).

Pictures are glint's own renders at the variant pictures' size, cached the same way.
"""

from __future__ import annotations

import json
import logging
import re
import textwrap
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

import numpy as np

import glint
from glint.compiler.catalog.loader import snippets_root
from glint.compiler.catalog.tiers import TIERS, tier_choice, tier_table
from glint.compiler.markdown import (
    fenced,
    md_code,
    md_prose,
    md_text,
    path_url,
    safe_image,
    safe_link,
    table,
    url_part,
)
from glint.compiler.render.images import flip_error, png_pixels
from glint.compiler.scene.model import Scene, load_scene

from .channels import live_shader
from .live_canvas import LIVE_DIR, VARIANT_SIZE, canvas_html
from .measured import load_bench
from .pictures import SIZE, TIME, render_cached

log = logging.getLogger(__name__)

SCENE_PICTURES = PurePosixPath("img") / "scenes"
SCENES_PAGE = PurePosixPath("scenes.md")
TIERS_PAGE = PurePosixPath("tiers.md")
GALLERY_PAGE = PurePosixPath("gallery.md")
GALLERY_SIZE = (768, 432)  # the gallery's large pictures, four times the variant pictures' width
LIVE_SIZE = VARIANT_SIZE  # small: a software rasteriser draws several on one page


@dataclass
class ScenePages:
    pages: dict[PurePosixPath, str] = field(default_factory=dict)
    files: dict[PurePosixPath, bytes] = field(default_factory=dict)


def example_scenes() -> list[Path]:
    """The example scenes, the default first, then by name."""
    files = sorted((snippets_root() / "scenes").glob("*.toml"))
    return sorted(files, key=lambda f: (f.stem != "default", f.stem))


def scene_pages(
    source: Path,
    cache_dir: Path | None,
    pictured: Collection[str] | None = None,
    scenes: Sequence[Path] | None = None,
) -> ScenePages:
    """The scene reference and the tiers page of the example scenes (or of `scenes`). Pictures
    only with a cache folder, and only of the scenes (by stem) in `pictured` when given."""
    scenes = example_scenes() if scenes is None else scenes
    out = ScenePages()
    renders: dict[tuple[str, str], PurePosixPath] = {}
    pixels: dict[tuple[str, str], np.ndarray] = {}
    live_tiers: dict[tuple[str, str], PurePosixPath] = {}
    meshes: dict[str, PurePosixPath] = {}
    large: dict[str, PurePosixPath] = {}
    for scene in scenes:
        pictures = cache_dir is not None and (pictured is None or scene.stem in pictured)
        if is_mesh_example(scene):
            # rasterized programs, not a ShaderToy shader: one picture at the scene's own
            # tier, no live canvas, not on the tiers page (the bench leaves it out too)
            png = _render_mesh(scene, cache_dir) if pictures and cache_dir else None
            if png is not None:
                meshes[scene.stem] = SCENE_PICTURES / f"{scene.stem}.png"
                out.files[meshes[scene.stem]] = png
            continue
        # the scene as written (its own tier: the gallery's large picture), then at every
        # tier (pictured, and live in the tabs of the tiers page and the gallery)
        for tier in (None, *TIERS):
            shader = _compose(scene, tier)
            if shader is None:
                continue
            if tier is None:
                if pictures and cache_dir:  # the gallery's large picture, at its own tier
                    png = _render(shader, scene, "its own tier", cache_dir, GALLERY_SIZE)
                    if png is not None:
                        large[scene.stem] = SCENE_PICTURES / f"{scene.stem}-large.png"
                        out.files[large[scene.stem]] = png
                continue
            path = LIVE_DIR / f"scene-{scene.stem}-{tier}.glsl"
            live_text, channel_files = live_shader(shader)
            out.files[path] = live_text.encode("utf-8")
            out.files.update(channel_files)
            live_tiers[(scene.stem, tier)] = path
            png = _render(shader, scene, tier, cache_dir) if pictures and cache_dir else None
            if png is not None:
                picture = SCENE_PICTURES / f"{scene.stem}-{tier}.png"
                out.files[picture] = png
                renders[(scene.stem, tier)] = picture
                pixels[(scene.stem, tier)] = png_pixels(png)
    out.pages[SCENES_PAGE] = scene_reference_page()
    out.pages[GALLERY_PAGE] = gallery_page(large, live_tiers, meshes, scenes)
    bench = load_bench(source).tiers
    out.pages[TIERS_PAGE] = tiers_page(renders, pixels, bench, live_tiers, scenes)
    return out


def is_mesh_example(scene: Path) -> bool:
    """Whether an example scene is a mesh scene (rasterized: `glint render` draws it, but it
    has no ShaderToy shader, no live canvas and no row in the tier bench)."""
    return load_scene(scene).is_mesh


def _render_mesh(scene: Path, cache_dir: Path) -> bytes | None:
    try:
        return render_cached(glint.compose_mesh(scene), cache_dir)[0]
    except glint.InputError as error:
        log.warning("site: mesh scene %s does not render: %s", scene.name, error)
        return None


def _compose(scene: Path, tier: str | None) -> glint.Shader | None:
    """The scene at `tier` (its own where None), or None, with a warning, where it fails."""
    try:
        return glint.compose(scene, tier=tier)
    except glint.InputError as error:
        log.warning("site: %s does not compose at %s: %s", scene.name, tier or "its tier", error)
        return None


def _render(
    shader: glint.Shader, scene: Path, tier: str, cache_dir: Path, size: tuple[int, int] = SIZE
) -> bytes | None:
    try:
        return render_cached(shader, cache_dir, size)[0]
    except glint.InputError as error:
        log.warning("site: %s does not render at %s: %s", scene.name, tier, error)
        return None


# --- the scene reference ------------------------------------------------------------------


def scene_reference_page() -> str:
    """Every key of a scene file, generated from the scene model; the example scenes are in
    the gallery (gallery_page)."""
    schema = Scene.model_json_schema()
    defs: dict[str, Any] = schema.get("$defs", {})
    parts = [
        "# Scene reference\n\n",
        "A scene is a TOML file that `glint compose` and `glint render` take (without one they "
        "use the embedded default scene). Nothing in it runs code. Every key below is "
        "generated from the scene model, so it is exactly what glint accepts: an unknown key "
        "or a value out of range is an error that names it. The example scenes, with their "
        "pictures, live canvases and files, are in the [gallery](gallery.md).\n\n",
        "## Top level\n\n",
        _keys_table(schema, defs),
        "\n",
    ]
    for name in sorted(defs):
        model = defs[name]
        parts.append(f"## {md_text(name)} {{ #{_anchor(name)} }}\n\n")
        if model.get("description"):
            parts.append(f"{md_prose(_sentence(model['description']))}\n\n")
        parts += [_keys_table(model, defs), "\n"]
    return "".join(parts)


def gallery_page(
    large: Mapping[str, PurePosixPath],
    live: Mapping[tuple[str, str], PurePosixPath] | None = None,
    meshes: Mapping[str, PurePosixPath] | None = None,
    scenes: Sequence[Path] | None = None,
) -> str:
    """Every example scene (or each of `scenes`): its description, a large picture at its own
    tier (`large`, by stem), the scene live at each tier in tabs (`live`, by stem and tier),
    and its files. A mesh scene's picture is in `meshes`; it has no live canvas."""
    scenes = example_scenes() if scenes is None else scenes
    live = live or {}
    meshes = meshes or {}
    parts = [
        "# Gallery\n\n",
        "Every example scene of `snippets/scenes/`: glint's render at the scene's own tier, the "
        "scene running live in your browser at each tier (switch with the tabs; drag to orbit, "
        "the sliders set its lights, materials and exposure), and the files that make it. "
        "Each is `glint compose` and `glint render` of the TOML below; every key is in the "
        "[scene reference](scenes.md).\n\n",
    ]
    for scene in scenes:
        loaded = load_scene(scene)
        parts.append(f"## {md_text(scene.stem)}\n\n")
        if loaded.description:
            parts.append(f"{md_prose(_sentence(loaded.description))}\n\n")
        if is_mesh_example(scene):
            parts.append(_mesh_example(scene, meshes.get(scene.stem)))
            continue
        picture = large.get(scene.stem)
        if picture is not None:
            parts.append(
                f"{_picture(f'the {scene.stem} scene', picture)}\n\n"
                f"{_render_command(scene)} ({GALLERY_SIZE[0]}x{GALLERY_SIZE[1]} pixels, time "
                f"{TIME:g}).\n\n"
            )
        parts.append(_live_tabs(scene.stem, live))
        parts.append(f"The scene, {md_code(f'snippets/scenes/{scene.name}')}:\n\n")
        parts.append(fenced(scene.read_text(encoding="utf-8"), "toml") + "\n")
        if loaded.geometry is not None:  # the user's own GLSL the scene names
            parts.append(f"{md_code(loaded.geometry.file)}, the scene's own distance function:\n\n")
            parts.append(fenced(loaded.geometry.source, "glsl") + "\n")
    return "".join(parts)


def _mesh_example(scene: Path, picture: PurePosixPath | None) -> str:
    """A mesh scene on the scene reference: its picture, why it has no live canvas, its TOML."""
    parts = []
    if picture is not None:
        parts.append(
            f"{_picture(f'the {scene.stem} scene', picture)}\n\n"
            f"{_render_command(scene)} ({SIZE[0]}x{SIZE[1]} pixels, time {TIME:g}).\n\n"
        )
    parts.append(
        "A mesh scene, rasterized from a vertex and a fragment shader per material "
        "(`glint compose --target mesh-webgl2`): no live canvas, which runs ShaderToy "
        "shaders.\n\n"
    )
    parts.append(fenced(scene.read_text(encoding="utf-8"), "toml") + "\n")
    return "".join(parts)


def _picture(alt: str, picture: PurePosixPath) -> str:
    """A scene's picture (under img/scenes) with `alt` as its text."""
    return safe_image(md_text(alt), path_url(picture))


def _render_command(scene: Path) -> str:
    return md_code(f"glint render snippets/scenes/{scene.name}")


def _anchor(name: str) -> str:
    """A heading's id: the schema's model name, lower case, nothing but letters, digits, `_`
    and `-` (an attr_list id)."""
    return re.sub(r"[^a-z0-9_-]", "-", name.lower())


def _sentence(value: str) -> str:
    return " ".join(value.split())


def _keys_table(model: dict[str, Any], defs: Mapping[str, Any]) -> str:
    required = set(model.get("required", []))
    rows = []
    for key, prop in model.get("properties", {}).items():
        default = "required" if key in required else _default(prop)
        description = _sentence(prop.get("description", ""))
        rows.append([md_code(key), _type(prop, defs), default, md_prose(description)])
    if not rows:
        return "No keys.\n"
    return table(["key", "type", "default", "what it is"], rows)


def _default(prop: Mapping[str, Any]) -> str:
    if "default" not in prop:
        return ""
    value = prop["default"]
    if value is None:
        return "absent"
    if isinstance(value, dict):
        return "its defaults" if value else "{}"
    return md_code(json.dumps(value))


def _type(prop: Mapping[str, Any], defs: Mapping[str, Any]) -> str:
    """A schema type as a reader reads it: links for tables, ranges and choices inline."""
    if "$ref" in prop:
        name = prop["$ref"].rsplit("/", 1)[-1]
        return f"{safe_link(md_text(name), f'#{_anchor(name)}')} table"
    for union in ("anyOf", "oneOf"):
        if union in prop:
            kinds = [k for k in prop[union] if k.get("type") != "null"]
            shown = " or ".join(_type(k, defs) for k in kinds)
            return shown + (" (may be absent)" if len(kinds) < len(prop[union]) else "")
    if "enum" in prop:
        return "one of " + ", ".join(md_code(json.dumps(v)) for v in prop["enum"])
    if "const" in prop:
        return md_code(json.dumps(prop["const"]))
    kind = prop.get("type", "")
    if kind == "array":
        item = _type(prop.get("items", {}), defs)
        size = prop.get("minItems")
        if size is not None and size == prop.get("maxItems"):
            return f"{size} × {item}"
        least = f", at least {size}" if size else ""
        return f"list of {item}{least}"
    if kind == "object":
        values = prop.get("additionalProperties")
        if isinstance(values, dict):
            return f"table of {_type(values, defs)}"
        return "table"
    bounds = []
    for key, sign in (("minimum", "≥"), ("exclusiveMinimum", ">"), ("maximum", "≤"),
                      ("exclusiveMaximum", "<")):  # fmt: skip
        if key in prop:
            bounds.append(f"{sign} {prop[key]:g}")
    shown = {"number": "number", "string": "string", "boolean": "true or false",
             "integer": "integer"}.get(kind, md_text(kind) or "any")  # fmt: skip
    return shown + (f" ({', '.join(bounds)})" if bounds else "")


# --- the tiers ---------------------------------------------------------------------------


def tiers_page(
    renders: Mapping[tuple[str, str], PurePosixPath],
    pixels: Mapping[tuple[str, str], np.ndarray],
    bench: Mapping[tuple[str, str], Mapping[str, Any]],
    live: Mapping[tuple[str, str], PurePosixPath] | None = None,
    scenes: Sequence[Path] | None = None,
) -> str:
    """The slot-by-tier table, then per example scene (or each of `scenes`) its pictures at
    every tier with FLIP and frame time, and its live canvases (by scene stem and tier, in
    `live`) in one tab per tier."""
    scenes = example_scenes() if scenes is None else scenes
    live = live or {}
    table_ = tier_table()
    slots = sorted({slot for tier in TIERS for slot in table_.get(tier, {})})
    rows = []
    for slot in slots:
        row = [safe_link(md_code(slot), f"catalog/slots/{url_part(slot)}.md")]
        for tier in TIERS:
            variant = tier_choice(table_, tier, slot)
            page = f"catalog/{url_part(f'{slot}.{variant}')}.md"
            row.append(safe_link(md_code(variant), page) if variant else "–")
        rows.append(row)
    parts = [
        "# Tiers\n\n",
        "A tier picks one variant per slot: `fast` trades accuracy for time, `reference` "
        "takes the most accurate, `balanced` sits between (`glint compose --tier`, or "
        "`[quality] tier` in a scene). A scene only takes the slots its content needs, so a "
        "slot below may not appear in a given shader (`glint compose --explain` says why).\n\n",
        "## Slot by tier\n\n",
        table(["slot", *TIERS], rows),
        "\n## Example scenes at every tier\n\n",
        "Each picture is glint's render; FLIP is the mean error against the same scene at the "
        "reference tier; the frame time is from `glint bench` (see [Benchmark](bench/bench.md) "
        "for its machine).\n\n",
    ]
    meshes = [md_text(scene.stem) for scene in scenes if is_mesh_example(scene)]
    if meshes:
        parts.append(
            f"Mesh scenes ({', '.join(meshes)}) are not here: their materials choose their own "
            "models, and the bench measures the tiers of ShaderToy shaders.\n\n"
        )
    for scene in scenes:
        if is_mesh_example(scene):
            continue
        parts.append(f"### {md_text(scene.stem)}\n\n")
        cells = []
        truth = pixels.get((scene.stem, "reference"))
        for tier in TIERS:
            picture = renders.get((scene.stem, tier))
            shown = _picture(f"{scene.stem} at {tier}", picture) if picture else "–"
            flip = "–"
            if truth is not None and (scene.stem, tier) in pixels:
                flip = f"{flip_error(truth, pixels[(scene.stem, tier)]):.4f}"
            measured = bench.get((scene.stem, tier))
            ms = f"{measured['frame_ms']:.2f} ms" if measured else "–"
            cells.append([md_code(tier), shown, flip, ms])
        parts.append(table(["tier", "picture", "FLIP vs reference", "frame time"], cells) + "\n")
        parts.append(_live_tabs(scene.stem, live))
    return "".join(parts)


def _live_tabs(stem: str, live: Mapping[tuple[str, str], PurePosixPath]) -> str:
    """One tab per tier, each with the scene at that tier running live (a canvas starts only
    when its tab is shown: live-canvas.js starts canvases as they come into view)."""
    tabs = []
    for tier in TIERS:
        if (stem, tier) in live:
            canvas = canvas_html(live[(stem, tier)], LIVE_SIZE, f"the {stem} scene at {tier}, live")
            tabs.append(f'=== "{md_text(tier)}"\n\n' + textwrap.indent(canvas, "    ") + "\n")
    if not tabs:
        return ""
    return "Live, one tab per tier:\n\n" + "".join(tabs)
