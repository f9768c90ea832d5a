"""Mesh scenes: the scene model's errors, mesh files read with trimesh, the built-in shapes'
normals, and the command line's answers to bad input."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from mesh_scenes import mesh_scene, raymarched_scene

from glint.compiler.compose.mesh.geometry import builtin_mesh, model_matrix, normal_matrix
from glint.compiler.errors import InputError
from glint.compiler.scene.mesh_files import smooth_normals
from glint.compiler.scene.model import parse_scene, scene_from_dict
from glint.compiler.scene.shapes import Mesh

MATERIAL = '\nmaterial = "m"\n[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n'


def _file_scene(name: str) -> str:
    return f'[[objects]]\nshape = "mesh"\nfile = "{name}"' + MATERIAL


TETRAHEDRON = """v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
f 1 3 2
f 1 2 4
f 1 4 3
f 2 3 4
"""


def _error(data: dict) -> str:
    with pytest.raises(InputError) as caught:
        scene_from_dict(data, "scene.toml")
    return caught.value.message


def test_mixing_meshes_and_sdf_objects_names_the_key() -> None:
    data = mesh_scene()
    data["objects"] = [*data["objects"], {"shape": "sphere", "material": "red"}]
    message = _error(data)
    assert message.startswith("scene.toml: objects[1].shape: 'sphere' in a scene with meshes")
    assert "all meshes" in message


def test_bad_builtin_subdivisions_and_sources() -> None:
    data = mesh_scene()
    data["objects"][0]["builtin"] = "teapot"
    assert "objects[0].builtin: unknown value 'teapot'" in _error(data)
    data = mesh_scene(subdivisions=9)
    assert "objects[0].subdivisions: input should be less than or equal to 7" in _error(data)
    data = mesh_scene()
    data["objects"][0]["file"] = "x.obj"
    assert "give file (a mesh file) or builtin" in _error(data)


def test_missing_mesh_file_names_the_key(tmp_path: Path) -> None:
    text = _file_scene("nope.obj")
    with pytest.raises(InputError) as caught:
        parse_scene(text, str(tmp_path / "scene.toml"))
    assert "objects[0].file: nope.obj: no such file" in caught.value.message
    assert "relative to the scene file" in caught.value.message


def test_mesh_keys_are_refused_on_raymarched_scenes() -> None:
    data = raymarched_scene()
    data["materials"] = {"red": {"albedo": [1.0, 0.0, 0.0], "shading": "flat"}}
    assert "materials.red.shading: only mesh scenes" in _error(data)
    data = raymarched_scene() | {"mesh": {"shading": "flat"}}
    assert "mesh: only mesh scenes" in _error(data)
    data = mesh_scene(shading="smooth")
    assert "mesh.shading: unknown value 'smooth'" in _error(data)


def test_obj_file_without_normals_gets_smooth_ones(tmp_path: Path) -> None:
    (tmp_path / "tet.obj").write_text(TETRAHEDRON)
    text = _file_scene("tet.obj")
    scene = parse_scene(text, str(tmp_path / "scene.toml"))
    mesh = scene.objects[0]
    assert isinstance(mesh, Mesh) and scene.is_mesh
    arrays = mesh.arrays
    assert arrays.positions.shape == (4, 3) and arrays.indices.shape == (4, 3)
    assert np.allclose(np.linalg.norm(arrays.normals, axis=1), 1.0, atol=1e-6)
    # the vertex at the origin is shared by three faces facing -x, -y, -z: its smooth normal
    # points away from the body
    assert np.all(arrays.normals[0] < -0.3)


def test_obj_file_normals_are_kept(tmp_path: Path) -> None:
    lines = TETRAHEDRON.splitlines()
    vertices, faces = lines[:4], lines[4:]
    with_normals = [
        *vertices,
        "vn 0 0 1",
        *[f"f {' '.join(f'{i}//1' for i in f.split()[1:])}" for f in faces],
    ]
    (tmp_path / "tet.obj").write_text("\n".join(with_normals) + "\n")
    text = _file_scene("tet.obj")
    mesh = parse_scene(text, str(tmp_path / "scene.toml")).objects[0]
    assert isinstance(mesh, Mesh)
    arrays = mesh.arrays
    assert np.allclose(arrays.normals, [0.0, 0.0, 1.0])


def _random_mesh(seed: int) -> tuple[np.ndarray, np.ndarray]:
    """An irregular closed surface: a sphere's vertices moved at random, and one degenerate
    face (three times the same vertex) that the normals must leave out."""
    sphere = builtin_mesh("icosphere", 2)
    rng = np.random.default_rng(seed)
    scale = rng.uniform(0.7, 1.3, (len(sphere.positions), 1))
    vertices = sphere.positions.astype(np.float64) * scale
    faces = np.vstack([sphere.indices.astype(np.int64), [[0, 0, 0]]])
    return vertices, faces


def test_smooth_normals_are_trimeshs_without_its_slow_loop() -> None:
    import trimesh

    vertices, faces = _random_mesh(7)
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    # trimesh's own formula (its loop: the form it takes without scipy)
    theirs = trimesh.geometry.weighted_vertex_normals(
        len(vertices), faces, mesh.face_normals, mesh.face_angles, use_loop=True
    )
    ours = smooth_normals(vertices, faces)
    ours /= np.linalg.norm(ours, axis=1, keepdims=True)
    assert np.abs(ours - theirs).max() < 1e-12


def test_a_mesh_file_with_a_nan_vertex_or_a_bad_index_names_it(tmp_path: Path) -> None:
    (tmp_path / "nan.obj").write_text(TETRAHEDRON.replace("v 1 0 0", "v 1 nan 0"))
    with pytest.raises(InputError) as caught:
        parse_scene(_file_scene("nan.obj"), str(tmp_path / "scene.toml"))
    assert "objects[0].file: " in caught.value.message
    assert "vertex 2 is not a finite float32 position (1.0, nan, 0.0)" in caught.value.message
    (tmp_path / "huge.obj").write_text(TETRAHEDRON.replace("v 1 0 0", "v 1e39 0 0"))
    with pytest.raises(InputError, match="vertex 2 is not a finite float32 position"):
        parse_scene(_file_scene("huge.obj"), str(tmp_path / "scene.toml"))


def test_a_mesh_file_past_the_limits_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import glint.compiler.scene.mesh_files as mesh_files

    (tmp_path / "tet.obj").write_text(TETRAHEDRON)
    monkeypatch.setattr(mesh_files, "MAX_TRIANGLES", 3)
    with pytest.raises(InputError, match="4 triangles, more than the 3 glint draws"):
        parse_scene(_file_scene("tet.obj"), str(tmp_path / "scene.toml"))
    monkeypatch.setattr(mesh_files, "MESH_FILE_LIMIT", 16)
    with pytest.raises(InputError, match="larger than the .* MiB glint reads for a mesh file"):
        parse_scene(_file_scene("tet.obj"), str(tmp_path / "scene.toml"))


def test_archives_and_unknown_suffixes_are_not_mesh_files(tmp_path: Path) -> None:
    for name in ("model.zip", "model.tar.gz", "model.txt"):
        (tmp_path / name).write_bytes(b"PK\x03\x04")
        with pytest.raises(InputError, match="not a mesh format glint reads"):
            parse_scene(_file_scene(name), str(tmp_path / "scene.toml"))


@pytest.mark.parametrize("name", ["uv_sphere", "icosphere"])
def test_sphere_normals_are_their_positions(name: str) -> None:
    arrays = builtin_mesh(name, 2)
    assert np.allclose(np.linalg.norm(arrays.positions, axis=1), 1.0, atol=1e-6)
    assert np.allclose(arrays.normals, arrays.positions, atol=1e-6)
    assert arrays.indices.max() < len(arrays.positions)


def test_torus_and_cube_normals_are_exact() -> None:
    torus = builtin_mesh("torus", 2)
    ring = torus.positions * [1.0, 0.0, 1.0]
    ring /= np.linalg.norm(ring, axis=1, keepdims=True)
    assert np.allclose(torus.positions - ring - 0.25 * torus.normals, 0.0, atol=1e-6)
    cube = builtin_mesh("cube", 1)
    # every normal is the axis on which its vertex lies on the face
    assert np.allclose(np.abs(cube.normals).sum(axis=1), 1.0)
    assert np.allclose((cube.positions * cube.normals).sum(axis=1), 1.0)
    # each triangle's vertices share one normal (flat faces)
    tri = cube.normals[cube.indices]
    assert np.allclose(tri[:, 0], tri[:, 1]) and np.allclose(tri[:, 0], tri[:, 2])


def test_placement_matrices() -> None:
    data = mesh_scene()
    data["objects"][0] |= {"position": [1.0, 2.0, 3.0], "rotation": [0.0, 90.0, 0.0], "scale": 2.0}
    mesh = scene_from_dict(data).objects[0]
    model = model_matrix(mesh)
    # Ry(90°) takes +x to -z; then scale 2 and move
    assert np.allclose(model @ [1.0, 0.0, 0.0, 1.0], [1.0, 2.0, 1.0, 1.0])
    assert np.allclose(normal_matrix(mesh) @ [1.0, 0.0, 0.0], [0.0, 0.0, -0.5])


def _glint(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
    )


def test_cli_bad_mesh_scenes_exit_1_without_traceback(tmp_path: Path) -> None:
    (tmp_path / "mixed.toml").write_text(
        '[[objects]]\nshape = "mesh"\nbuiltin = "cube"\nmaterial = "m"\n'
        '[[objects]]\nshape = "box"\nsize = [1.0, 1.0, 1.0]\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n"
    )
    (tmp_path / "cube.toml").write_text(
        '[[objects]]\nshape = "mesh"\nbuiltin = "cube"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n"
    )
    mixed = _glint("compose", "mixed.toml", "--target", "mesh-webgl2", "-o", "x", cwd=tmp_path)
    assert mixed.returncode == 1 and "Traceback" not in mixed.stderr
    assert "objects[1].shape: 'box' in a scene with meshes" in mixed.stderr
    shadertoy = _glint("compose", "cube.toml", cwd=tmp_path)
    assert shadertoy.returncode == 1 and "Traceback" not in shadertoy.stderr
    assert "--target mesh-webgl2 or mesh-desktop" in shadertoy.stderr
    missing_output = _glint("compose", "cube.toml", "--target", "mesh-desktop", cwd=tmp_path)
    assert missing_output.returncode == 2 and "give -o BASE" in missing_output.stderr
    written = _glint(
        "compose", "cube.toml", "--target", "mesh-webgl2", "-o", "out.glsl", cwd=tmp_path
    )
    assert written.returncode == 0, written.stderr
    for name in ("out.vert", "out.frag", "out.background.frag"):
        assert (tmp_path / name).read_text().startswith("#version 300 es\n")
