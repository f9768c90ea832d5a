"""The camera of a mesh scene as view and projection matrices, with the rays of the
raymarched camera snippets (snippets/camera/): the same eye, the same basis, the same focal.

A camera snippet sends the ray normalize(uv.x·right + uv.y·up + focal·forward) through the
pixel at uv = (2·fragCoord − iResolution.xy) / iResolution.y, with forward toward the target,
right = normalize(forward × ŷ) (x when forward is vertical: camera_right) and up =
right × forward. So a point at depth d along forward and (x, y) across is seen at uv =
focal·(x, y)/d: a perspective of vertical field of view 2·atan(1/focal) whose x is divided by
the aspect ratio.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from glint.compiler.scene.model import OrbitCamera, Scene


@dataclass(frozen=True)
class CameraMatrices:
    eye: np.ndarray  # world position, float64 (3,)
    view: np.ndarray  # 4x4 row-major, world to camera (camera looks down -z)
    projection: np.ndarray  # 4x4 row-major, camera to clip space


def eye_and_target(
    scene: Scene, time: float, mouse: tuple[float, ...], size: tuple[int, int]
) -> tuple[np.ndarray, np.ndarray]:
    """Where the camera is at `time` (and after a mouse drag, as camera.orbit reads iMouse)."""
    camera = scene.camera
    target = np.asarray(camera.target, dtype=np.float64)
    if not isinstance(camera, OrbitCamera):
        return np.asarray(camera.position, dtype=np.float64), target
    angle, height = math.radians(camera.start) + time * camera.speed, camera.height
    if mouse[0] > 0.0 or mouse[1] > 0.0:
        angle = 2.0 * math.pi * mouse[0] / size[0]
        height = 2.0 * camera.height * mouse[1] / size[1]
    offset = [camera.radius * math.cos(angle), height, camera.radius * math.sin(angle)]
    return target + np.asarray(offset), target


def camera_matrices(
    scene: Scene,
    size: tuple[int, int],
    depth_range: tuple[float, float],
    time: float = 0.0,
    mouse: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0),
) -> CameraMatrices:
    """View and projection for an image of `size` (width, height); `depth_range` is (near,
    far) along the view direction."""
    eye, target = eye_and_target(scene, time, mouse, size)
    forward = _unit(target - eye)
    right = camera_right(forward)
    up = np.cross(right, forward)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, up, -forward
    view[:3, 3] = -view[:3, :3] @ eye
    near, far = depth_range
    focal, aspect = scene.camera.focal, size[0] / size[1]
    projection = np.zeros((4, 4))
    projection[0, 0] = focal / aspect
    projection[1, 1] = focal
    projection[2, 2] = (far + near) / (near - far)
    projection[2, 3] = 2.0 * far * near / (near - far)
    projection[3, 2] = -1.0
    return CameraMatrices(eye, view, projection)


def camera_right(forward: np.ndarray) -> np.ndarray:
    """The screen's x for a unit line of sight, as the camera snippets take it:
    normalize(forward × ŷ), except straight up or down (the same test as theirs), where that
    vanishes and it is the world's x."""
    if forward[0] ** 2 + forward[2] ** 2 > 1e-8:
        return _unit(np.cross(forward, [0.0, 1.0, 0.0]))
    return np.array([1.0, 0.0, 0.0])


def depth_range(eye: np.ndarray, centre: np.ndarray, radius: float) -> tuple[float, float]:
    """Near and far planes that hold a bounding sphere, as tight as the depth buffer needs."""
    distance = float(np.linalg.norm(centre - eye))
    far = (distance + radius) * 1.01 + 1e-3
    near = max(distance - radius, far * 1e-4) * 0.9
    return near, far


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)
