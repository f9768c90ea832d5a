"""Every public function and method of `import glint`, called with bad arguments of every kind,
raises a GlintError (InputError, UsageError, EnvironmentProblem) with one clear message that
names what is wrong; never TypeError, ValueError, OverflowError, KeyError or ZeroDivisionError
from inside, and never a render started for a request that cannot be served."""

from __future__ import annotations

import math
import os
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import glint
from glint.compiler.render import runner
from glint.compiler.render.images import image_stats

ROOT = Path(__file__).resolve().parents[2]
DEFAULT = ROOT / "snippets" / "scenes" / "default.toml"
MESH_SCENE = ROOT / "snippets" / "scenes" / "eight_models.toml"
CODE = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n"
HUGE = 10**400  # an int no float holds
SCENE = tomllib.loads(DEFAULT.read_text(encoding="utf-8"))


@dataclass
class Things:
    """What the calls are made on: composed shaders, the catalog, an image, paths."""

    shader: glint.Shader
    mesh: glint.MeshShader
    catalog: glint.Catalog
    image: glint.Image
    folder: str
    missing: str


@pytest.fixture(scope="module")
def things(tmp_path_factory: pytest.TempPathFactory) -> Things:
    folder = tmp_path_factory.mktemp("bad-calls")
    pixels = np.zeros((4, 8, 4), np.float32)
    image = glint.Image(pixels[:, :, :3], image_stats(pixels), "test", "300 es", 0.0, 0.0, 0)
    return Things(
        shader=glint.compose(DEFAULT),
        mesh=glint.compose_mesh(MESH_SCENE),
        catalog=glint.catalog(),
        image=image,
        folder=str(folder),
        missing=str(folder / "no" / "such" / "file.glsl"),
    )


def scene_with(path: str, value: object) -> dict[str, Any]:
    """The default scene as a dict with the value at a dotted path (list items by index)."""
    scene = tomllib.loads(DEFAULT.read_text(encoding="utf-8"))
    keys = path.split(".")
    node: Any = scene
    for key in keys[:-1]:
        node = node[int(key)] if isinstance(node, list) else node[key]
    last = keys[-1]
    if isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value
    return scene


Call = Callable[[Things], object]
# (id, the call, a regex its message must match: the argument or what is wrong)
BAD_CALLS: list[tuple[str, Call, str]] = [
    # compose: the scene
    ("compose-scene-int", lambda t: glint.compose(123), "scene is the path .* not int"),
    ("compose-scene-list", lambda t: glint.compose([]), "not list"),
    ("compose-scene-bytes", lambda t: glint.compose(b"x.toml"), "not bytes"),
    ("compose-scene-empty", lambda t: glint.compose(""), "scene: expected a path"),
    ("compose-scene-missing", lambda t: glint.compose(t.missing), "no such scene file"),
    ("compose-scene-folder", lambda t: glint.compose(t.folder), "is a folder, expected a scene"),
    ("compose-scene-nul", lambda t: glint.compose("a\0b.toml"), "NUL"),
    ("compose-dict-empty", lambda t: glint.compose({}), "materials: required key"),
    ("compose-dict-int-key", lambda t: glint.compose({1: 2}), r"<scene>"),
    ("compose-dict-objects-str", lambda t: glint.compose({"objects": "x"}), "objects"),
    (
        "compose-dict-radius-str",
        lambda t: glint.compose(scene_with("objects.0.radius", "big")),
        r"objects\[0\]\.radius",
    ),
    (
        "compose-dict-radius-huge",
        lambda t: glint.compose(scene_with("objects.0.radius", HUGE)),
        r"objects\[0\]\.radius",
    ),
    (
        "compose-dict-radius-none",
        lambda t: glint.compose(scene_with("objects.0.radius", None)),
        r"objects\[0\]\.radius",
    ),
    (
        "compose-dict-albedo-short",
        lambda t: glint.compose(scene_with("materials.red.albedo", [1.0])),
        "albedo",
    ),
    ("compose-dict-camera-none", lambda t: glint.compose({**SCENE, "camera": None}), "camera"),
    (
        "compose-dict-unknown-material",
        lambda t: glint.compose(scene_with("objects.0.material", "nope")),
        "nope",
    ),
    # compose: the options
    ("compose-target-none", lambda t: glint.compose(target=None), "target: unknown value None"),
    ("compose-target-int", lambda t: glint.compose(target=1), "target: unknown value 1"),
    ("compose-target-list", lambda t: glint.compose(target=[]), "target: unknown value"),
    ("compose-target-unknown", lambda t: glint.compose(target="vulkan"), "target: unknown"),
    ("compose-tier-int", lambda t: glint.compose(tier=1), "tier: unknown value 1"),
    ("compose-tier-empty", lambda t: glint.compose(tier=""), "tier: unknown value ''"),
    ("compose-tier-dict", lambda t: glint.compose(tier={}), "tier: unknown value"),
    ("compose-variants-int", lambda t: glint.compose(variants=1), "variants: expected a dict"),
    ("compose-variants-str", lambda t: glint.compose(variants="shadow=hard"), "variants: exp"),
    ("compose-variants-list", lambda t: glint.compose(variants=[("a", "b")]), "variants: exp"),
    ("compose-variants-int-key", lambda t: glint.compose(variants={1: "x"}), "variants: keys"),
    ("compose-variants-none-value", lambda t: glint.compose(variants={"D": None}), "variants"),
    ("compose-variants-unknown-slot", lambda t: glint.compose(variants={"no": "x"}), "slot"),
    ("compose-variants-unknown", lambda t: glint.compose(variants={"D": "x"}), "variant 'x'"),
    ("compose-budget-str", lambda t: glint.compose(budget="5"), "budget: expected a number"),
    ("compose-budget-list", lambda t: glint.compose(budget=[]), "budget: expected a number"),
    ("compose-budget-bool", lambda t: glint.compose(budget=True), "budget: expected a number"),
    ("compose-budget-nan", lambda t: glint.compose(budget=math.nan), "budget: expected a fin"),
    ("compose-budget-inf", lambda t: glint.compose(budget=math.inf), "budget: expected a fin"),
    ("compose-budget-huge-int", lambda t: glint.compose(budget=HUGE), "budget: expected a fin"),
    ("compose-budget-zero", lambda t: glint.compose(budget=0), "budget: expected a positive"),
    ("compose-budget-negative", lambda t: glint.compose(budget=-1.0), "budget: expected a pos"),
    ("compose-budget-tiny", lambda t: glint.compose(budget=1e-300), "below the cheapest"),
    ("compose-uniforms-str", lambda t: glint.compose(params_as_uniforms="yes"), "True or False"),
    ("compose-uniforms-none", lambda t: glint.compose(params_as_uniforms=None), "True or False"),
    ("compose-uniforms-int", lambda t: glint.compose(params_as_uniforms=1), "True or False"),
    ("compose-uniforms-shadertoy", lambda t: glint.compose(params_as_uniforms=True), "webgl2"),
    # compose_mesh
    ("mesh-scene-int", lambda t: glint.compose_mesh(7), "not int"),
    ("mesh-scene-not-mesh", lambda t: glint.compose_mesh(DEFAULT), "is for mesh scenes"),
    ("mesh-scene-empty", lambda t: glint.compose_mesh(""), "scene: expected a path"),
    ("mesh-target-none", lambda t: glint.compose_mesh(MESH_SCENE, target=None), "target"),
    ("mesh-target-glsl", lambda t: glint.compose_mesh(MESH_SCENE, target="webgl2"), "target"),
    ("mesh-tier-list", lambda t: glint.compose_mesh(MESH_SCENE, tier=["fast"]), "tier"),
    ("mesh-variants-int", lambda t: glint.compose_mesh(MESH_SCENE, variants=3), "variants"),
    # render: what to draw
    ("render-none", lambda t: glint.render(None), "render takes .* not NoneType"),
    ("render-int", lambda t: glint.render(123), "not int"),
    ("render-bytes", lambda t: glint.render(CODE.encode()), "not bytes"),
    ("render-list", lambda t: glint.render([CODE]), "not list"),
    ("render-empty", lambda t: glint.render(""), "shader: expected a path"),
    ("render-missing", lambda t: glint.render(t.missing), "no such file"),
    ("render-folder", lambda t: glint.render(t.folder), "is a folder"),
    ("render-webgl2", lambda t: glint.render(t.shader.retarget("webgl2")), "target is webgl2"),
    ("render-missing-scene", lambda t: glint.render("missing.toml"), "no such scene file"),
    ("render-bad-scene", lambda t: glint.render({**SCENE, "camera": 1}), "camera"),
    # render: size
    ("render-size-none", lambda t: glint.render(CODE, size=None), "size: expected a sequence"),
    ("render-size-int", lambda t: glint.render(CODE, size=64), "size: expected a sequence"),
    ("render-size-str", lambda t: glint.render(CODE, size="64x36"), "size: expected a seq"),
    ("render-size-dict", lambda t: glint.render(CODE, size={"w": 1}), "size: expected a seq"),
    ("render-size-one", lambda t: glint.render(CODE, size=(64,)), "size: expected 2 numbers"),
    ("render-size-three", lambda t: glint.render(CODE, size=(1, 2, 3)), "size: expected 2"),
    ("render-size-float", lambda t: glint.render(CODE, size=(8.5, 8)), r"size\[0\]: .*whole"),
    ("render-size-str-item", lambda t: glint.render(CODE, size=("8", 8)), r"size\[0\]"),
    ("render-size-bool", lambda t: glint.render(CODE, size=(8, True)), r"size\[1\]"),
    ("render-size-nan", lambda t: glint.render(CODE, size=(math.nan, 8)), r"size\[0\]"),
    ("render-size-inf", lambda t: glint.render(CODE, size=(math.inf, 8)), r"size\[0\]"),
    ("render-size-zero", lambda t: glint.render(CODE, size=(0, 36)), "size: width and height"),
    ("render-size-negative", lambda t: glint.render(CODE, size=(-1, 8)), "must be 1..8192"),
    ("render-size-huge", lambda t: glint.render(CODE, size=(HUGE, 8)), "must be 1..8192"),
    ("render-size-past-max", lambda t: glint.render(CODE, size=(8193, 8)), "must be 1..8192"),
    ("render-size-array", lambda t: glint.render(CODE, size=np.zeros((2, 2))), "size"),
    # render: uniforms and time limit
    ("render-time-none", lambda t: glint.render(CODE, time=None), "time: expected a number"),
    ("render-time-str", lambda t: glint.render(CODE, time="1"), "time: expected a number"),
    ("render-time-nan", lambda t: glint.render(CODE, time=math.nan), "time: expected a finite"),
    ("render-time-inf", lambda t: glint.render(CODE, time=-math.inf), "time: expected a fin"),
    ("render-time-1e308", lambda t: glint.render(CODE, time=1e308), "time: .*GLSL float"),
    ("render-time-huge-int", lambda t: glint.render(CODE, time=HUGE), "time: expected a fin"),
    ("render-frame-none", lambda t: glint.render(CODE, frame=None), "frame: expected a whole"),
    ("render-frame-float", lambda t: glint.render(CODE, frame=1.0), "frame: expected a whole"),
    ("render-frame-str", lambda t: glint.render(CODE, frame="1"), "frame: expected a whole"),
    ("render-frame-negative", lambda t: glint.render(CODE, frame=-1), "frame: must be from 0"),
    ("render-frame-int64", lambda t: glint.render(CODE, frame=2**40), "frame: must be from 0"),
    ("render-mouse-none", lambda t: glint.render(CODE, mouse=None), "mouse: expected a seq"),
    ("render-mouse-int", lambda t: glint.render(CODE, mouse=5), "mouse: expected a seq"),
    ("render-mouse-str", lambda t: glint.render(CODE, mouse="1,2,3,4"), "mouse: expected a"),
    ("render-mouse-three", lambda t: glint.render(CODE, mouse=(1, 2, 3)), "mouse: expected 4"),
    ("render-mouse-str-item", lambda t: glint.render(CODE, mouse=("a", 0, 0, 0)), r"mouse\[0\]"),
    ("render-mouse-nan", lambda t: glint.render(CODE, mouse=(0, math.nan, 0, 0)), r"mouse\[1\]"),
    ("render-mouse-huge", lambda t: glint.render(CODE, mouse=(0, 0, HUGE, 0)), r"mouse\[2\]"),
    ("render-mouse-1e39", lambda t: glint.render(CODE, mouse=(0, 0, 0, 1e39)), r"mouse\[3\]"),
    ("render-timeout-none", lambda t: glint.render(CODE, timeout=None), "timeout: expected a"),
    ("render-timeout-str", lambda t: glint.render(CODE, timeout="5"), "timeout: expected a"),
    ("render-timeout-zero", lambda t: glint.render(CODE, timeout=0), "timeout: must be more"),
    ("render-timeout-negative", lambda t: glint.render(CODE, timeout=-1), "timeout: must be"),
    ("render-timeout-nan", lambda t: glint.render(CODE, timeout=math.nan), "timeout: expected"),
    ("render-timeout-inf", lambda t: glint.render(CODE, timeout=math.inf), "timeout: expected"),
    ("render-timeout-1e308", lambda t: glint.render(CODE, timeout=1e308), "at most 3600"),
    ("render-timeout-huge-int", lambda t: glint.render(CODE, timeout=HUGE), "timeout: exp"),
    ("render-mesh-time-nan", lambda t: glint.render(t.mesh, time=math.nan), "time: expected"),
    ("render-mesh-size-str", lambda t: glint.render(t.mesh, size=(8, "x")), r"size\[1\]"),
    ("render-mesh-timeout-zero", lambda t: glint.render(t.mesh, timeout=0), "timeout: must"),
    # lint_shader
    ("lint-none", lambda t: glint.lint_shader(None), "shader: expected GLSL text"),
    ("lint-int", lambda t: glint.lint_shader(123), "shader: expected GLSL text"),
    ("lint-bytes", lambda t: glint.lint_shader(CODE.encode()), "shader: expected GLSL text"),
    ("lint-list", lambda t: glint.lint_shader([CODE]), "shader: expected GLSL text"),
    ("lint-empty", lambda t: glint.lint_shader(""), "shader: expected a path"),
    ("lint-stdin", lambda t: glint.lint_shader("-"), "standard input"),
    ("lint-missing", lambda t: glint.lint_shader(t.missing), "no such file or directory"),
    ("lint-select-int", lambda t: glint.lint_shader(CODE, select=1), "select: expected a str"),
    ("lint-select-int-item", lambda t: glint.lint_shader(CODE, select=[1]), "select: every"),
    ("lint-select-dict", lambda t: glint.lint_shader(CODE, select={"N": 1}), "select: exp"),
    ("lint-select-empty", lambda t: glint.lint_shader(CODE, select=""), "select: no rule"),
    ("lint-select-unknown", lambda t: glint.lint_shader(CODE, select="XX9"), "unknown rule"),
    ("lint-ignore-int", lambda t: glint.lint_shader(CODE, ignore=1), "ignore: expected a str"),
    ("lint-ignore-none-item", lambda t: glint.lint_shader(CODE, ignore=[None]), "ignore: ev"),
    ("lint-target-int", lambda t: glint.lint_shader(CODE, target=1), "target: unknown value"),
    ("lint-target-empty", lambda t: glint.lint_shader(CODE, target=""), "target: unknown"),
    ("lint-target-mesh", lambda t: glint.lint_shader(CODE, target="hlsl"), "target: unknown"),
    ("lint-glslang-str", lambda t: glint.lint_shader(CODE, glslang="no"), "glslang: expected"),
    ("lint-glslang-none", lambda t: glint.lint_shader(CODE, glslang=None), "glslang: expected"),
    # catalog
    ("catalog-int-id", lambda t: t.catalog[1], "snippet id is a str"),
    ("catalog-none-id", lambda t: t.catalog[None], "snippet id is a str"),
    ("catalog-list-id", lambda t: t.catalog[[]], "snippet id is a str"),
    ("catalog-empty-id", lambda t: t.catalog[""], "unknown snippet ''"),
    ("catalog-unknown-id", lambda t: t.catalog["D.nope"], "unknown snippet 'D.nope'"),
    ("catalog-near-id", lambda t: t.catalog["D.ggz"], "did you mean D.ggx"),
    ("catalog-slot-int", lambda t: t.catalog.slot(1), "slot: expected a str"),
    ("catalog-slot-unknown", lambda t: t.catalog.slot("nope"), "unknown slot 'nope'; slots: D"),
    ("snippet-lang-unknown", lambda t: t.catalog["D.ggx"].standalone("x"), "unknown language"),
    ("snippet-lang-none", lambda t: t.catalog["D.ggx"].standalone(None), "unknown language"),
    # Shader
    ("shader-retarget-none", lambda t: t.shader.retarget(None), "target: unknown value"),
    ("shader-retarget-mesh", lambda t: t.shader.retarget("mesh-desktop"), "target: unknown"),
    ("shader-retarget-uniforms-str", lambda t: t.shader.retarget("webgl2", "y"), "True or F"),
    ("shader-retarget-uniforms-hlsl", lambda t: t.shader.retarget("hlsl", True), "webgl2"),
    ("shader-split-webgl2", lambda t: t.shader.retarget("webgl2").split_common(), "shadertoy"),
    ("shader-validate-hlsl", lambda t: t.shader.retarget("hlsl").validate(), "checks GLSL"),
    ("shader-save-none", lambda t: t.shader.save(None), "path: expected a path"),
    ("shader-save-int", lambda t: t.shader.save(1), "path: expected a path"),
    ("shader-save-empty", lambda t: t.shader.save(""), "path: expected a path"),
    ("shader-save-folder", lambda t: t.shader.save(t.folder), "cannot write .*a folder"),
    ("shader-save-missing", lambda t: t.shader.save(t.missing), "cannot write .*No such"),
    # MeshShader
    ("mesh-save-none", lambda t: t.mesh.save(None), "base: expected a path"),
    ("mesh-save-int", lambda t: t.mesh.save(1), "base: expected a path"),
    ("mesh-save-empty", lambda t: t.mesh.save(""), "base: expected a path"),
    ("mesh-save-dot", lambda t: t.mesh.save("."), "base: '.' names a folder"),
    ("mesh-save-missing", lambda t: t.mesh.save(t.missing), "cannot write"),
    ("mesh-files-list", lambda t: t.mesh.files([]), "base: expected a path"),
    ("mesh-files-parent", lambda t: t.mesh.files(".."), "names a folder"),
    # Image
    ("image-save-none", lambda t: t.image.save(None), "path: expected a path"),
    ("image-save-int", lambda t: t.image.save(1), "path: expected a path"),
    ("image-save-bytes", lambda t: t.image.save(b"x.png"), "path: expected a path"),
    ("image-save-empty", lambda t: t.image.save(""), "path: expected a path"),
    ("image-save-folder", lambda t: t.image.save(t.folder), "cannot write"),
    ("image-save-missing", lambda t: t.image.save(t.missing), "cannot write"),
]


def test_there_are_enough_bad_calls() -> None:
    assert len(BAD_CALLS) >= 90
    assert len({name for name, _, _ in BAD_CALLS}) == len(BAD_CALLS)


@pytest.mark.parametrize("call, pattern", [c[1:] for c in BAD_CALLS], ids=[c[0] for c in BAD_CALLS])
def test_a_bad_call_raises_a_glint_error(
    things: Things,
    call: Call,
    pattern: str,
    monkeypatch: pytest.MonkeyPatch,
    tmp_path: Path,
) -> None:
    def no_render(*args: object, **kwargs: object) -> str:
        raise AssertionError("a render started for a request that should have been refused")

    monkeypatch.setattr(runner, "_run_worker", no_render)
    monkeypatch.chdir(tmp_path)  # a call that wrongly writes leaves its file here, not in the repo
    with pytest.raises(Exception) as raised:  # noqa: PT011 - the type is what is checked
        call(things)
    error = raised.value
    assert isinstance(error, glint.GlintError), f"{type(error).__name__}: {error}"
    assert error.message.strip() and "Traceback" not in error.message
    assert error.exit_code in (1, 2)
    assert re.search(pattern, error.message), error.message
    assert os.listdir(tmp_path) == []


def test_an_unknown_snippet_is_a_key_error_too(things: Things) -> None:
    """Mapping lookups keep working: `in`, `get` and `except KeyError` see an unknown id."""
    assert "D.nope" not in things.catalog and 1 not in things.catalog
    assert things.catalog.get("D.nope") is None
    with pytest.raises(KeyError, match="did you mean D.ggx"):
        things.catalog["D.ggz"]
    with pytest.raises(glint.InputError) as raised:
        things.catalog["D.ggz"]
    assert str(raised.value) == raised.value.message  # not quoted, as KeyError's str would


def test_an_image_with_no_finite_value_shows_itself() -> None:
    pixels = np.full((2, 3, 4), np.nan, np.float32)
    image = glint.Image(pixels[:, :, :3], image_stats(pixels), "test", "300 es", 0.0, 0.0, 0)
    assert image.stats["mean"] == [None, None, None]
    assert "mean RGB n/a, n/a, n/a" in repr(image) and "NaN pixels 6" in repr(image)
