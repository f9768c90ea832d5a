"""`glint.compose_mesh`: a mesh scene to its vertex and fragment shaders (`glint compose
--target mesh-webgl2|mesh-desktop`), and the drawing of one for `glint.render`."""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from glint.compiler.catalog.tiers import TIERS
from glint.compiler.errors import UsageError
from glint.compiler.target.mesh import MESH_TARGETS

from . import _args
from ._shader import _check_choice, load_scene

if TYPE_CHECKING:
    from glint.compiler.compose.mesh.pipeline import MeshComposition, MeshProgram
    from glint.compiler.render.runner import RenderResult
    from glint.compiler.scene.model import Scene
    from glint.compiler.target.glslang import Diagnostic

    from ._shader import SceneInput


@dataclass(frozen=True, eq=False, repr=False)
class MeshShader:
    """A composed mesh scene: per material a program (`programs[i].vertex.text`,
    `.fragment.text`, its shading mode and plan), and `background`, the full-screen shader
    drawn before the meshes (ShaderToy's uniforms: iResolution, iTime, iMouse)."""

    composition: MeshComposition

    @property
    def target(self) -> str:
        return self.composition.target

    @property
    def scene(self) -> Scene:
        return self.composition.scene

    @property
    def programs(self) -> list[MeshProgram]:
        return self.composition.programs

    @property
    def background(self) -> str:
        return self.composition.background.text

    def files(self, base: str | os.PathLike[str]) -> dict[Path, str]:
        """The shaders by the file names `save` gives them (see MeshComposition.files)."""
        base = _args.path("base", base)
        if Path(base).name in ("", ".", ".."):
            raise UsageError(
                f"base: {base!r} names a folder; give a file stem such as 'out/sphere' "
                "(sphere.vert, sphere.frag, sphere.background.frag)"
            )
        return self.composition.files(base)

    def save(self, base: str | os.PathLike[str]) -> list[Path]:
        """Write every shader (atomically) beside BASE; returns the paths written."""
        from glint.compiler.files import is_null_device, write_atomic

        files = self.files(base)  # checks `base` first
        # into the null device: every program thrown away, nothing written beside the device
        thrown = is_null_device(base)
        written = []
        for path, text in files.items():
            where = Path(base) if thrown else path
            write_atomic(where, text.encode("utf-8"))
            written.append(where)
        return list(dict.fromkeys(written))

    def validate(self) -> list[Diagnostic]:
        """glslangValidator's diagnostics for every stage, at snippet file and line."""
        return self.composition.validate()

    def explain(self) -> str:
        return self.composition.explain()

    def __repr__(self) -> str:
        modes = ", ".join(f"{p.material}: {p.shading}" for p in self.programs)
        return f"<glint.MeshShader scene '{self.scene.name}', {self.target} target, {modes}>"


def compose_mesh(
    scene: SceneInput = None,
    *,
    target: str = "mesh-desktop",
    tier: str | None = None,
    variants: Mapping[str, str] | None = None,
) -> MeshShader:
    """Compose a mesh scene (objects with shape = "mesh") for `target` (mesh-webgl2: GLSL ES
    3.00, mesh-desktop: GLSL 3.30), as `glint compose --target mesh-...` does."""
    from glint.compiler.compose.mesh.pipeline import compose_mesh_scene

    _check_choice("target", target, MESH_TARGETS)
    if tier is not None:
        _check_choice("tier", tier, TIERS)
    variants = _args.str_mapping("variants", variants)
    model = load_scene(scene)
    return MeshShader(compose_mesh_scene(model, target, tier, variants))


def draw_mesh_shader(
    shader: MeshShader,
    size: tuple[int, int],
    time: float,
    mouse: tuple[float, float, float, float],
    timeout: float,
) -> RenderResult:
    """Draw a composed mesh scene: its meshes' triangles, placed, with the camera at `time`."""
    import numpy as np

    from glint.compiler.compose.mesh.camera import camera_matrices, depth_range, eye_and_target
    from glint.compiler.compose.mesh.geometry import mesh_arrays, model_matrix, normal_matrix
    from glint.compiler.render.mesh_runner import MeshDraw, MeshView, render_meshes
    from glint.compiler.scene.shapes import Mesh

    draws = []
    world = []
    for program in shader.programs:
        for obj in program.scene.objects:
            assert isinstance(obj, Mesh)
            arrays = mesh_arrays(obj)
            model = model_matrix(obj)
            world.append(arrays.positions @ model[:3, :3].T + model[:3, 3])
            draws.append(
                MeshDraw(
                    name=program.material,
                    vertex=program.vertex.text,
                    fragment=program.fragment.text,
                    positions=arrays.positions,
                    normals=arrays.normals,
                    indices=arrays.indices,
                    model=model,
                    normal_matrix=normal_matrix(obj),
                )
            )
    points = np.concatenate(world)
    centre = (points.min(axis=0) + points.max(axis=0)) / 2.0
    radius = float(np.linalg.norm(points - centre, axis=1).max())
    eye, _ = eye_and_target(shader.scene, time, mouse, size)
    camera = camera_matrices(shader.scene, size, depth_range(eye, centre, radius), time, mouse)
    view = MeshView(camera.eye, camera.view, camera.projection)
    width, height = size
    return render_meshes(shader.background, draws, view, width, height, time, mouse, timeout)
