"""Headless rendering of ShaderToy shaders (moderngl on EGL) in a watched child process.

The names below are loaded on first use, so that `glint.compiler.render.limits` (which the
command line's argument parser uses) comes without numpy and Pillow.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from glint.compiler.render.images import flip_error, image_stats, save_png
    from glint.compiler.render.runner import RenderResult, render, render_full

__all__ = ["RenderResult", "flip_error", "image_stats", "render", "render_full", "save_png"]

_MODULE_OF = {
    "flip_error": "images",
    "image_stats": "images",
    "save_png": "images",
    "RenderResult": "runner",
    "render": "runner",
    "render_full": "runner",
}


def __getattr__(name: str) -> Any:
    if name in _MODULE_OF:
        module = importlib.import_module(f"glint.compiler.render.{_MODULE_OF[name]}")
        return getattr(module, name)
    raise AttributeError(f"module 'glint.compiler.render' has no attribute {name!r}")
