"""The triangles of a mesh object: read from its file when the scene loads (scene/mesh_files.py),
or a built-in shape made here with exact normals; and the matrices that place it in the world.

Arrays are in the object's own space; `model_matrix` places them as every object is placed
(p' = R · (s · p) + position, R = Rz · Ry · Rx) and `normal_matrix` turns its normals.
"""

from __future__ import annotations

import math

import numpy as np

from glint.compiler.compose.codegen.field_code import rotation_matrix
from glint.compiler.scene.mesh_files import MeshArrays, indexed_triangles
from glint.compiler.scene.shapes import Mesh, Placed

TORUS_RADIUS = 1.0  # the built-in torus: ring radius (centre to the middle of the tube)
TORUS_THICKNESS = 0.25  # and tube radius, the defaults of the SDF torus


def builtin_mesh(name: str, level: int) -> MeshArrays:
    """A built-in shape at refinement `level` (see Mesh.subdivisions), with analytic normals."""
    if name == "uv_sphere":
        return _uv_sphere(8 << level, 4 << level)
    if name == "icosphere":
        import trimesh

        sphere = trimesh.creation.icosphere(subdivisions=level, radius=1.0)
        positions = np.asarray(sphere.vertices)
        return indexed_triangles(positions, positions, np.asarray(sphere.faces))
    if name == "torus":
        return _torus(8 << level, 4 << level)
    if name == "cube":
        return _cube(1 << level)
    raise ValueError(f"unknown builtin mesh {name!r}")


def mesh_arrays(mesh: Mesh) -> MeshArrays:
    """The triangles of a mesh object (a file's were read when the scene was loaded)."""
    if mesh.builtin is not None:
        return builtin_mesh(mesh.builtin, mesh.subdivisions)
    return mesh.arrays


def _grid_faces(rows: int, columns: int, wrap: bool) -> np.ndarray:
    """Two triangles per cell of a (rows + 1) x (columns + 1) vertex grid; `wrap` joins the
    last column to the first (a closed ring of `columns` vertices per row)."""
    width = columns if wrap else columns + 1
    i, j = np.meshgrid(np.arange(rows), np.arange(columns), indexing="ij")
    a = i * width + j
    b = i * width + (j + 1) % width
    c = (i + 1) * width + j
    d = (i + 1) * width + (j + 1) % width
    return np.stack([np.stack([a, c, b], -1), np.stack([b, c, d], -1)], -2).reshape(-1, 3)


def _uv_sphere(segments: int, bands: int) -> MeshArrays:
    """The unit sphere by latitude and longitude; its normal is its position."""
    theta = np.linspace(0.0, math.pi, bands + 1)[:, None]  # from the north pole
    phi = np.arange(segments)[None, :] * (2.0 * math.pi / segments)
    x, y, z = np.broadcast_arrays(
        np.sin(theta) * np.cos(phi), np.cos(theta), np.sin(theta) * np.sin(phi)
    )
    positions = np.stack([x, y, z], -1).reshape(-1, 3)
    return indexed_triangles(positions, positions, _grid_faces(bands, segments, wrap=True))


def _torus(ring_segments: int, tube_segments: int) -> MeshArrays:
    """The torus of the SDF torus (ring in the xz plane); its normal points away from the
    middle of the tube."""
    u = np.arange(ring_segments)[:, None] * (2.0 * math.pi / ring_segments)
    v = np.arange(tube_segments)[None, :] * (2.0 * math.pi / tube_segments)
    u, v = np.broadcast_arrays(u, v)
    normals = np.stack([np.cos(v) * np.cos(u), np.sin(v), np.cos(v) * np.sin(u)], -1)
    centres = np.stack([np.cos(u), np.zeros_like(u), np.sin(u)], -1) * TORUS_RADIUS
    positions = centres + TORUS_THICKNESS * normals
    faces = _torus_faces(ring_segments, tube_segments)
    return indexed_triangles(positions.reshape(-1, 3), normals.reshape(-1, 3), faces)


def _torus_faces(rows: int, columns: int) -> np.ndarray:
    """A grid closed in both directions."""
    i, j = np.meshgrid(np.arange(rows), np.arange(columns), indexing="ij")
    a = i * columns + j
    b = i * columns + (j + 1) % columns
    c = ((i + 1) % rows) * columns + j
    d = ((i + 1) % rows) * columns + (j + 1) % columns
    return np.stack([np.stack([a, b, c], -1), np.stack([b, d, c], -1)], -2).reshape(-1, 3)


def _cube(cells: int) -> MeshArrays:
    """The cube [-1, 1]^3, each face its own grid of cells x cells quads: a face's vertices
    are its own, so every normal is the face's."""
    positions, normals, faces = [], [], []
    t = np.linspace(-1.0, 1.0, cells + 1)
    s, r = np.meshgrid(t, t, indexing="ij")
    for axis in range(3):
        for sign in (1.0, -1.0):
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            p = np.zeros((cells + 1, cells + 1, 3))
            p[..., axis] = sign
            p[..., u_axis] = s if sign > 0 else r
            p[..., v_axis] = r if sign > 0 else s
            base = sum(len(x) for x in positions)
            positions.append(p.reshape(-1, 3))
            n = np.zeros_like(p.reshape(-1, 3))
            n[:, axis] = sign
            normals.append(n)
            faces.append(_grid_faces(cells, cells, wrap=False) + base)
    return indexed_triangles(
        np.concatenate(positions), np.concatenate(normals), np.concatenate(faces)
    )


def model_matrix(obj: Placed) -> np.ndarray:
    """4x4 (float64, row-major) of p' = R · (s · p) + position."""
    matrix = np.eye(4)
    matrix[:3, :3] = np.asarray(rotation_matrix(obj.rotation)) * obj.scale
    matrix[:3, 3] = obj.position
    return matrix


def normal_matrix(obj: Placed) -> np.ndarray:
    """3x3 world-space normal matrix: the inverse transpose of the model matrix's 3x3, which
    for R · s is R / s (the shader normalizes the result)."""
    return np.linalg.inv(model_matrix(obj)[:3, :3]).T
