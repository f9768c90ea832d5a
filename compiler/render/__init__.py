"""Headless rendering of ShaderToy shaders (moderngl on EGL) in a watched child process."""

from glint.compiler.render.images import flip_error, image_stats, save_png
from glint.compiler.render.runner import RenderResult, render, render_full

__all__ = ["RenderResult", "flip_error", "image_stats", "render", "render_full", "save_png"]
