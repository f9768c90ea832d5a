"""C002 glslang-warning."""

from __future__ import annotations

from .. import register
from ._glslang import GlslangRule


@register
class GlslangWarning(GlslangRule):
    """Finds what glslangValidator warns about in the wrapped file.

    Why is this bad?
        glslang's warnings mark code that some drivers treat differently or not at all
        (deprecated features, extension behaviour).

    Example:
        #extension GL_EXT_draw_buffers : enable

    Fix:
        Remove the directive: GL_EXT_draw_buffers is WebGL 1's extension, and several outputs
        are core in GLSL ES 3.00 (ShaderToy's passes write one colour anyway).

    Fix safety:
        No fix.

    References:
        - glslang, the Khronos reference front end: https://github.com/KhronosGroup/glslang
        - GLSL ES 3.00 spec §3.4 (Preprocessor: `#extension ... : enable` of an extension the
          compiler does not support is a warning)
    """

    code = "C002"
    name = "glslang-warning"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "correctness"
    severity = "warning"
    wanted = "warning"
