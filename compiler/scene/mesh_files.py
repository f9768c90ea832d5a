"""Mesh files as a scene reads them: a file's indexed triangles and normals, read with trimesh
within limits (a regular file, its size, its triangle count), so that a scene with a mesh object
is whole once loaded. Placing the triangles in the world is the composer's
(compose/mesh/geometry.py).
"""

from __future__ import annotations

import io
import logging
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from glint.compiler.errors import InputError
from glint.compiler.files import MiB, read_user_file
from glint.compiler.scene.values import FLOAT32_MAX

# Mesh files are read whole into memory, then parsed by trimesh: at most this many bytes (an
# OBJ of 64 MiB holds about a million triangles) and this many triangles in one mesh.
MESH_FILE_LIMIT = 64 * MiB
MAX_TRIANGLES = 4_000_000
# The mesh formats read (by suffix): trimesh's formats of triangles, without the archives it
# also opens (a small zip can expand past any limit) and the point and 2D formats.
_MESH_FORMATS = ("glb", "gltf", "obj", "off", "ply", "stl")


@dataclass(frozen=True)
class MeshArrays:
    """Indexed triangles: float32 positions and unit normals (V x 3), uint32 indices (F x 3)."""

    positions: np.ndarray
    normals: np.ndarray
    indices: np.ndarray


def read_mesh_file(path: Path, key: str) -> MeshArrays:
    """The triangles of a mesh file, with its own vertex normals when it has them, else smooth
    (corner-angle weighted) vertex normals as trimesh computes them. `key` names the scene key
    in messages. The file (and any file it refers to: an OBJ's material library, a glTF's
    buffers) is read only if it is a regular file of at most MESH_FILE_LIMIT bytes."""
    import trimesh

    if not path.exists() and not path.is_symlink():
        raise InputError(
            f"{key}: {path.name}: no such file (looked for {path}); the path is relative to "
            "the scene file"
        )
    file_type = path.suffix.lstrip(".").lower()
    if file_type not in _MESH_FORMATS:
        raise InputError(
            f"{key}: {path}: not a mesh format glint reads (by its suffix, {path.suffix!r}); "
            "expected one of ." + ", .".join(_MESH_FORMATS)
        )
    try:
        data = read_user_file(path, MESH_FILE_LIMIT, "mesh file")
    except InputError as exc:
        raise InputError(f"{key}: {exc.message}") from None
    # Without scipy trimesh logs a traceback as a warning before a fallback of its own; glint
    # does not ask trimesh for what needs scipy, and any such note is noise for the user.
    logging.getLogger("trimesh").setLevel(logging.ERROR)
    try:
        # process=False keeps the file's vertices, so its normals (if any) stay with them. A
        # file of several objects is a trimesh Scene: its meshes are joined, placed as it
        # places them (their normals then are computed here).
        loaded = trimesh.load(
            io.BytesIO(data), file_type=file_type, resolver=_Resolver(path), process=False
        )
        if isinstance(loaded, trimesh.Scene):
            loaded = loaded.dump(concatenate=True)
    except InputError as exc:
        raise InputError(f"{key}: {exc.message}") from None
    except Exception as exc:  # trimesh raises many kinds for a file it cannot read
        raise InputError(f"{key}: {path}: cannot read it as a mesh: {exc}") from None
    faces = np.asarray(getattr(loaded, "faces", np.zeros((0, 3))))
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        raise InputError(f"{key}: {path}: the file has no triangles")
    if len(faces) > MAX_TRIANGLES:
        raise InputError(
            f"{key}: {path}: {len(faces)} triangles, more than the {MAX_TRIANGLES} glint draws "
            "in one mesh; decimate it first"
        )
    vertices = np.asarray(loaded.vertices, dtype=np.float64)
    if faces.min() < 0 or faces.max() >= len(vertices):
        raise InputError(f"{key}: {path}: a face refers to a vertex the file does not have")
    bad = ~np.isfinite(vertices).all(axis=1) | (np.abs(vertices) > FLOAT32_MAX).any(axis=1)
    if bad.any():
        raise InputError(
            f"{key}: {path}: vertex {int(np.argmax(bad)) + 1} is not a finite float32 "
            f"position ({', '.join(repr(float(x)) for x in vertices[np.argmax(bad)])})"
        )
    normals = _file_normals(loaded, vertices.shape)
    if normals is None:
        normals = smooth_normals(vertices, faces)
    return indexed_triangles(vertices, normals, faces)


def _file_normals(loaded: Any, shape: tuple[int, ...]) -> np.ndarray | None:
    """The vertex normals the file gave, if any (trimesh keeps them as its cached normals;
    asking for `vertex_normals` would compute them when the file has none)."""
    cache = getattr(loaded, "_cache", None)
    if cache is None or "vertex_normals" not in cache:
        return None
    normals = np.asarray(loaded.vertex_normals, dtype=np.float64)
    if normals.shape != shape or not np.isfinite(normals).all():
        return None
    return normals


def smooth_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Vertex normals as trimesh's `vertex_normals` gives them (Thürrner and Wüthrich 1998,
    "Computing Vertex Normals from Polygonal Facets": each face's normal weighted by the
    face's angle at the vertex; degenerate faces left out), in time linear in the faces.
    trimesh computes them with a scipy sparse matrix, and without scipy with a loop whose
    time grows with vertices × faces (minutes for an OBJ of a few MB)."""
    import trimesh

    corners = vertices[faces]
    face_normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(face_normals, axis=1)
    ok = length > 0.0
    face_normals = face_normals[ok] / length[ok, None]
    angles = trimesh.triangles.angles(corners[ok])
    weighted = angles[:, :, None] * face_normals[:, None, :]  # faces x corners x 3
    summed = np.stack(
        [
            np.bincount(faces[ok].ravel(), weighted[..., axis].ravel(), len(vertices))
            for axis in range(3)
        ],
        axis=-1,
    )
    return summed


class _Resolver:
    """What a mesh file refers to (an OBJ's material library and textures, a glTF's buffers),
    looked up as trimesh's FilePathResolver does, beside the file and not above its folder,
    and read as the file itself is (read_user_file)."""

    def __init__(self, path: Path) -> None:
        import trimesh

        self._paths = trimesh.resolvers.FilePathResolver(str(path))
        self.file_name = path.name

    def get(self, name: str) -> bytes:
        for candidate in (name.strip(), name.strip().lstrip("/"), os.path.split(name)[-1]):
            try:
                found = self._paths.absolute(candidate)
            except ValueError:
                continue
            if found.exists():
                return read_user_file(found, MESH_FILE_LIMIT, "file a mesh refers to")
        raise FileNotFoundError(name)

    def __getitem__(self, name: str) -> bytes:
        return self.get(name)

    def namespaced(self, namespace: str) -> _Resolver:
        return _Resolver(Path(self._paths.parent) / namespace / self.file_name)


def indexed_triangles(positions: np.ndarray, normals: np.ndarray, faces: np.ndarray) -> MeshArrays:
    """The arrays as every mesh is kept: float32 positions and unit normals (a zero normal
    turned up), uint32 indices."""
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    unit = np.where(length > 0.0, normals / np.maximum(length, 1e-30), [0.0, 1.0, 0.0])
    return MeshArrays(
        positions=np.ascontiguousarray(positions, dtype=np.float32),
        normals=np.ascontiguousarray(unit, dtype=np.float32),
        indices=np.ascontiguousarray(faces, dtype=np.uint32),
    )
