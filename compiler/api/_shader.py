"""`glint.compose`: a scene (a TOML file, a dict, a Scene) to a `Shader`, as `glint compose`."""

from __future__ import annotations

import html
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from glint.compiler.catalog.tiers import TIERS
from glint.compiler.errors import UsageError
from glint.compiler.target.cross import LANGS
from glint.compiler.target.shadertoy import TARGETS

from . import _args

# What `compose` writes: the GLSL targets, and HLSL and MSL converted from the shadertoy one.
COMPOSE_TARGETS = TARGETS + LANGS

if TYPE_CHECKING:
    from glint.compiler.compose.linking.split import SplitShader
    from glint.compiler.compose.linking.uniform_params import UniformParam
    from glint.compiler.compose.planning.plan import Plan
    from glint.compiler.compose.units import Unit
    from glint.compiler.scene.model import Scene
    from glint.compiler.target.glslang import Diagnostic

    # What `compose` takes for a scene.
    SceneInput = str | os.PathLike[str] | Mapping[str, Any] | Scene | None


@dataclass(frozen=True, eq=False, repr=False)
class Shader:
    """A composed shader: `text` is what `glint compose` writes for the same scene and options.

    For the shadertoy target `text` pastes into ShaderToy's Image tab as it is; webgl2 and
    desktop are complete fragment shaders; hlsl and msl are the shadertoy shader converted
    through SPIR-V to an HLSL pixel shader / a Metal fragment function. `plan` holds each
    slot's use and variant and why, `units` the snippets and generated code in the order they
    were emitted. `uniforms` holds the parameters composed as uniforms (`params_as_uniforms`),
    as the shader's manifest lists them.
    """

    text: str
    target: str
    scene: Scene
    plan: Plan
    units: list[Unit]
    uniforms: tuple[UniformParam, ...] = ()

    @property
    def tier(self) -> str:
        return self.plan.tier

    @property
    def snippets(self) -> list[str]:
        """Ids of the catalog snippets in the shader, in order (the scene's own code left out)."""
        return [unit.id for unit in self.units if unit.slot != "scene"]

    def explain(self) -> str:
        """What `glint compose --explain` prints: each slot in or out and why, which variant
        fills it and why, the material paths the scene turns on."""
        from glint.compiler.compose.planning.explain import explain

        return explain(self.scene, self.plan)

    def validate(self) -> list[Diagnostic]:
        """glslangValidator's diagnostics for the shader, as `glint validate` prints them (at
        the snippet file and line); an empty list when it is valid."""
        from glint.compiler.target.glslang import validate

        if self.target in LANGS:
            raise UsageError(
                f"validate checks GLSL; this shader is {self.target.upper()} (compose it for a "
                f"GLSL target to validate it)"
            )
        return validate(self.text, f"<{self.scene.name}>", self.target)

    def retarget(self, target: str, params_as_uniforms: bool = False) -> Shader:
        """The same composition emitted for `target` (with `params_as_uniforms`, webgl2 only),
        without planning it again: what `compose` with those options gives for the scene."""
        from glint.compiler.compose.codegen.scene_code import generate
        from glint.compiler.compose.pipeline import emit_shader

        _check_choice("target", target, COMPOSE_TARGETS)
        params_as_uniforms = _args.flag("params_as_uniforms", params_as_uniforms)
        _check_uniforms(target, params_as_uniforms)
        emit_as = "shadertoy" if target in LANGS else target
        knobs = generate(self.scene, tier=self.plan.tier).knobs if params_as_uniforms else None
        composed = emit_shader(
            self.scene.name, self.plan, list(self.units), emit_as, params_as_uniforms,
            knobs=knobs,
        )  # fmt: skip
        return Shader(
            _converted(composed.text, target, self.scene.name),
            target,
            self.scene,
            self.plan,
            composed.units,
            tuple(composed.uniforms),
        )

    def split_common(self) -> SplitShader:
        """The shader as two ShaderToy tabs: the lighting library for the Common tab and a short
        Image tab that uses it (`glint compose --split common`); shadertoy target only."""
        from glint.compiler.compose.linking.split import split_common
        from glint.compiler.compose.pipeline import glint_version

        if self.target != "shadertoy":
            raise UsageError(f"--split common is for the shadertoy target, not {self.target}")
        return split_common(self.scene.name, self.plan, list(self.units), glint_version())

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write the shader to `path` (atomically, like `glint compose -o`); returns the path."""
        from glint.compiler.files import write_atomic

        path = _args.path("path", path)
        write_atomic(path, self.text.encode("utf-8"))
        return Path(path)

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        return f"<glint.Shader {self._summary()}>"

    def _summary(self) -> str:
        lines = self.text.count("\n")
        return (
            f"scene '{self.scene.name}', {self.target} target, tier {self.tier}, "
            f"{len(self.snippets)} snippets, {lines} lines"
        )

    def _repr_html_(self) -> str:
        """A header line and the code, in a scrolling box (Jupyter)."""
        return (
            f"<div><strong>glint shader</strong>: {html.escape(self._summary())}"
            '<pre style="max-height: 32em; overflow: auto">'
            f"<code>{html.escape(self.text)}</code></pre></div>"
        )


def compose(
    scene: SceneInput = None,
    *,
    target: str = "shadertoy",
    tier: str | None = None,
    variants: Mapping[str, str] | None = None,
    budget: float | None = None,
    params_as_uniforms: bool = False,
) -> Shader:
    """Compose a scene into one shader, as `glint compose` does.

    `scene` is the path of a scene TOML file, a dict with the same structure as the TOML, a
    `glint.compiler.scene.model.Scene`, or None for the embedded default scene. `target`,
    `tier`, `variants` ({slot: variant}) and `budget` (ns per pixel) are the command's
    `--target`, `--tier`, `--variant SLOT=VARIANT` and `--budget`; `params_as_uniforms` is
    `--params-as-uniforms` (webgl2 only). `target` "hlsl" or "msl" converts the shadertoy
    shader through SPIR-V (glslangValidator, SPIRV-Cross); EnvironmentProblem when a tool is
    missing.

    Raises InputError for a scene that is not valid (the message names the key path, the value
    and what was expected), an unknown slot or variant, or a budget below the cheapest
    combination; UsageError for an unknown target or tier or a budget that is not positive.
    """
    from glint.compiler.compose.pipeline import compose_scene

    _check_choice("target", target, COMPOSE_TARGETS)
    params_as_uniforms = _args.flag("params_as_uniforms", params_as_uniforms)
    _check_uniforms(target, params_as_uniforms)
    if tier is not None:
        _check_choice("tier", tier, TIERS)
    variants = _args.str_mapping("variants", variants)
    if budget is not None and not _args.number("budget", budget) > 0:
        raise UsageError(f"budget: expected a positive number of ns, got {budget!r}")
    model = load_scene(scene)
    emit_as = "shadertoy" if target in LANGS else target
    composed = compose_scene(model, emit_as, tier, variants, budget, params_as_uniforms)
    return Shader(
        _converted(composed.text, target, model.name),
        target,
        model,
        composed.plan,
        composed.units,
        tuple(composed.uniforms),
    )


def _converted(text: str, target: str, scene_name: str) -> str:
    """The shadertoy shader as HLSL or MSL for those targets; other targets' text as it is."""
    if target not in LANGS:
        return text
    from glint.compiler.target.cross import DESCRIPTIONS, cross_compile_image

    converted = cross_compile_image(text, target, f"<{scene_name}>")
    # glint's header (version, scene, tier, the snippets) survives as the converted file's own.
    header = [line for line in text.split("\n\n", 1)[0].splitlines() if line.startswith("//")]
    header[0] = header[0].replace("target shadertoy", f"target {target}")
    header[1:2] = [
        f"// {DESCRIPTIONS[target]}",
        "// Converted through SPIR-V (glslangValidator -V, then SPIRV-Cross).",
    ]
    return "\n".join(header) + "\n\n" + converted


def load_scene(scene: SceneInput) -> Scene:
    """The validated scene of a path, a dict, a Scene or None (the embedded default)."""
    from glint.compiler.scene import model as scenes

    if scene is None:
        return scenes.load_scene(None)
    if isinstance(scene, str | os.PathLike):
        return scenes.load_scene(_args.path("scene", scene))
    if isinstance(scene, scenes.Scene):
        return scene
    if isinstance(scene, Mapping):
        from glint.compiler.scene.model import scene_from_dict

        return scene_from_dict(scene)
    raise UsageError(
        f"a scene is the path of a TOML file, a dict or a Scene, not {type(scene).__name__}"
    )


def _check_uniforms(target: str, params_as_uniforms: bool) -> None:
    if params_as_uniforms and target in LANGS:
        raise UsageError(f"--params-as-uniforms needs --target webgl2, not {target}")


def _check_choice(name: str, value: str, choices: tuple[str, ...]) -> None:
    _args.choice(name, value, choices)


def is_source(value: object) -> bool:
    """Whether `value` is code rather than a path: a str that holds a line break."""
    return isinstance(value, str) and "\n" in value
