"""The picture on each variant's page: glint's own render of a scene composed with that variant,
so a reader sees what choosing it does rather than reading about it.

A slot with a preview scene made to show it (`snippets/previews/*.toml`, PREVIEWS: a roughness
sweep for the surface slots, long penumbrae for shadows, a small corner for AO, the same
corner in polished metal for specular occlusion) is shown there;
any other in the default scene where that uses the slot, else in the first example scene
(`snippets/scenes/*.toml`) whose plan uses it, named on the page. Library snippets (sdf
primitives, core helpers) fill no slot a scene can override, so they get no picture. A variant
that fails to compose or render gets no picture and a line saying so: one bad snippet must not
break the site.

Renders are cached by a hash of (shader text, size, time, glint version), so a rebuild that
changes no shader renders nothing; llvmpipe takes a fraction of a second per small picture.
"""

from __future__ import annotations

import hashlib
import logging
import os
from collections.abc import Collection, Iterable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path, PurePosixPath

import glint
from glint.compiler.catalog.loader import snippets_root
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.files import write_atomic
from glint.compiler.markdown import md_code
from glint.compiler.scene.model import load_scene

from .channels import live_shader

log = logging.getLogger(__name__)

PICTURE_DIR = PurePosixPath("img") / "variants"
SIZE = (192, 108)  # small: 83 renders on llvmpipe in well under a minute
TIME = 1.0
DEFAULT_SCENE = "the default scene"
OWN_SCENE = "a small scene made to show it"


@dataclass(frozen=True)
class Picture:
    """What a variant's page says about its picture: the image (under the docs folder) and the
    scene it shows, or why there is none."""

    path: PurePosixPath | None = None
    scene_file: str | None = None  # e.g. "snippets/scenes/lamp.toml"; None: the default scene
    note: str = ""  # why there is no picture, when `path` is None (Markdown, escaped here)
    shader: str = ""  # the composed shader the picture shows (ShaderToy Image-tab code)
    live: str = ""  # the same composition for the live canvas (webgl2, parameters as uniforms)
    own_scene: bool = False  # a small scene made for a library snippet (card_scenes.py)
    code: str = ""  # the variant's own code as both shaders hold it once: what a reader edits

    @property
    def scene(self) -> str:
        """The scene as the page names it (Markdown, its file name in a code span)."""
        if self.own_scene:
            return OWN_SCENE
        return f"the example scene {md_code(self.scene_file)}" if self.scene_file else DEFAULT_SCENE

    @property
    def scene_text(self) -> str:
        """The scene as plain text (an image's alt text)."""
        if self.own_scene:
            return OWN_SCENE
        return f"the example scene {self.scene_file}" if self.scene_file else DEFAULT_SCENE


@dataclass
class Pictures:
    """The pictures of a build: by snippet id, the PNG files to add to the docs folder, and how
    many were rendered rather than taken from the cache (0 for a rebuild)."""

    by_id: dict[str, Picture] = field(default_factory=dict)
    files: dict[PurePosixPath, bytes] = field(default_factory=dict)
    rendered: int = 0


def picture_path(snippet_id: str) -> PurePosixPath:
    return PICTURE_DIR / f"{snippet_id}.png"


def selection_from_env(value: str | None) -> Collection[str] | None:
    """Which variants get pictures, from $GLINT_SITE_PICTURES: unset or "all" for every one,
    "none" for none, else comma-separated snippet ids (the tests render only a few)."""
    if value is None or value.strip() == "all":
        return None
    if value.strip() == "none":
        return ()
    return tuple(part.strip() for part in value.split(",") if part.strip())


def variant_pictures(
    ids: Iterable[str], cache_dir: Path, only: Collection[str] | None = None
) -> Pictures:
    """The pictures of the variants `ids` (those in `only`, when given), rendered into
    `cache_dir` where it does not hold them already."""
    catalog = glint.catalog()
    result = Pictures()
    for snippet_id in ids:
        if only is not None and snippet_id not in only:
            continue
        snippet = catalog[snippet_id]
        result.by_id[snippet_id] = _picture(snippet.slot, snippet.variant, cache_dir, result)
    return result


def picture_composition(slot: str, variant: str) -> tuple[glint.Shader, str | None] | Picture:
    """The composition a variant's picture shows (the scene of `scene_using` with the variant)
    and that scene's file as the page names it; where there is none, the Picture that says
    why."""
    snippet_id = f"{slot}.{variant}"
    if _library(slot):
        return _own_scene_composition(snippet_id)
    scene = scene_using(slot)
    if scene is None:
        return Picture(note="No example scene uses this slot, so it has no picture.")
    path, scene_file = scene
    label = Picture(scene_file=scene_file).scene
    try:
        shader = glint.compose(path, variants={slot: variant})
    except glint.InputError as error:
        log.warning("site: no picture for %s: %s", snippet_id, error)
        return Picture(scene_file=scene_file, note=f"No picture: {label} fails to compose with it.")
    if shader.plan.choices.get(slot) != snippet_id:
        return Picture(scene_file=scene_file, note=f"No picture: {label} does not take it.")
    return shader, scene_file


def _own_scene_composition(snippet_id: str) -> tuple[glint.Shader, str | None] | Picture:
    """A library snippet's picture: the small scene of card_scenes.py that uses it (a shape, an
    intersection, a light), where it has one and the composition takes the snippet."""
    from .card_scenes import card_scene

    scene = card_scene(snippet_id)
    if scene is None:
        return Picture(note="A library snippet: no scene slot takes it, so it has no picture.")
    try:
        shader = glint.compose(scene)
    except glint.InputError as error:
        log.warning("site: no picture for %s: %s", snippet_id, error)
        return Picture(note="No picture: its scene fails to compose.", own_scene=True)
    if snippet_id not in {unit.id for unit in shader.units}:
        return Picture(note="No picture: its scene does not take it.", own_scene=True)
    return shader, None


def _library(slot: str) -> bool:
    """A snippet no scene slot takes (a shape, a light's term, a helper)."""
    spec = SLOTS.get(slot)
    return spec is None or spec.many


def _picture(slot: str, variant: str, cache_dir: Path, result: Pictures) -> Picture:
    """One variant's picture; its PNG goes into `result.files`."""
    snippet_id = f"{slot}.{variant}"
    composed = picture_composition(slot, variant)
    if isinstance(composed, Picture):
        return composed
    shader, scene_file = composed
    try:
        png, rendered = render_cached(shader, cache_dir)
    except glint.InputError as error:
        log.warning("site: no picture for %s: %s", snippet_id, error)
        label = Picture(scene_file=scene_file).scene
        return Picture(scene_file=scene_file, note=f"No picture: {label} fails to render.")
    result.rendered += rendered
    live, channel_files = live_shader(shader)  # emitted again, not composed
    result.files.update(channel_files)
    picture = Picture(
        path=picture_path(snippet_id),
        scene_file=scene_file,
        shader=shader.text,
        live=live,
        own_scene=_library(slot),
        code=editable_code(shader, snippet_id, live),
    )
    result.files[picture_path(snippet_id)] = png
    return picture


def editable_code(shader: glint.Shader, snippet_id: str, live: str) -> str:
    """The variant's code as the picture's shader and its live shader each hold it exactly once,
    so that the page's editor can put an edit in its place in both; "" where it cannot (the
    code absent, or found twice)."""
    body = next((unit.body for unit in shader.units if unit.id == snippet_id), "")
    if body.strip() and shader.text.count(body) == 1 and live.count(body) == 1:
        return body
    return ""


def render_cached(
    shader: glint.Shader | glint.MeshShader, cache_dir: Path, size: tuple[int, int] = SIZE
) -> tuple[bytes, bool]:
    """glint's render of `shader` (a ShaderToy shader, or a mesh scene's programs) at `size`
    (the pictures' by default) and the pictures' time as PNG, from `cache_dir` where it holds
    it, and whether it had to be rendered. Raises glint.InputError when it does not render."""
    cached = cache_dir / f"{cache_key(_shader_text(shader), size)}.png"
    if cached.is_file():
        return cached.read_bytes(), False
    png = glint.render(shader, size=size, time=TIME).to_png()
    cache_dir.mkdir(parents=True, exist_ok=True)
    write_atomic(cached, png)
    return png, True


def _shader_text(shader: glint.Shader | glint.MeshShader) -> str:
    """All the code a picture is drawn from: the one shader, or every stage of a mesh scene."""
    if isinstance(shader, glint.MeshShader):
        stages = [text for p in shader.programs for text in (p.vertex.text, p.fragment.text)]
        # the meshes (shapes, subdivisions, placement) are buffers and uniforms, not code
        return "\n".join([shader.scene.model_dump_json(), *stages, shader.background])
    return shader.text


def cache_key(text: str, size: tuple[int, int] = SIZE) -> str:
    """What a picture depends on: the shader, the size, the time and glint's version (the
    renderer's code is glint's)."""
    data = f"{glint.__version__}\n{size[0]}x{size[1]}\n{TIME!r}\n{text}"
    return hashlib.sha256(data.encode("utf-8")).hexdigest()


# The preview scene made to show a slot (snippets/previews/), where the default scene would
# hide its variants: a lobe's shape shows on a roughness sweep lit at a grazing angle, not on
# one sphere under a high sun. A slot not named here is shown in the scenes below.
PREVIEWS = {
    "D": "surface",
    "F": "surface",
    "V": "surface",
    "specular": "surface",
    "diffuse": "surface",
    "shadow": "penumbra",
    "ao": "corner",
    "specocc": "occluded_reflection",
}


def scene_using(slot: str) -> tuple[str | None, str | None] | None:
    """The scene to show a variant of `slot` in, as (path for glint.compose, file as the page
    names it): the slot's preview scene, else the default scene (None, None) if its plan uses
    the slot, else the first example scene that does."""
    preview = _preview_slots(PREVIEWS[slot]) if slot in PREVIEWS else None
    for path, name, slots in (*([preview] if preview else []), *_scene_slots()):
        if slot in slots:
            return path, name
    return None


@cache
def _preview_slots(preview: str) -> tuple[str, str, frozenset[str]] | None:
    """A preview scene (path, name) and the slots its plan fills (composed once per build),
    or None, with a warning, where it does not compose."""
    file = snippets_root() / "previews" / f"{preview}.toml"
    name = f"snippets/previews/{file.name}"
    try:
        return os.fspath(file), name, _slots_of(os.fspath(file))
    except glint.InputError as error:
        log.warning("site: scene %s does not compose: %s", name, error)
        return None


@cache
def _scene_slots() -> tuple[tuple[str | None, str | None, frozenset[str]], ...]:
    """Each candidate scene (path, name) and the slots its plan fills (composed once per build
    process): the default scene first, then the example scenes by name."""
    scenes: list[tuple[str | None, str | None]] = [(None, None)]
    for file in sorted((snippets_root() / "scenes").glob("*.toml")):
        # A variant's picture is a ShaderToy shader composed with the variant: mesh scenes
        # (rasterized, each material with its own models) are not candidates.
        if file.stem != "default" and not load_scene(file).is_mesh:
            scenes.append((os.fspath(file), f"snippets/scenes/{file.name}"))
    result = []
    for path, name in scenes:
        try:
            slots = _slots_of(path)
        except glint.InputError as error:
            log.warning("site: scene %s does not compose: %s", name, error)
            continue
        result.append((path, name, slots))
    return tuple(result)


def _slots_of(path: str | None) -> frozenset[str]:
    return frozenset(glint.compose(path).plan.choices)
