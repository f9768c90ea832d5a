"""C002 glslang-warning."""

from __future__ import annotations

from .. import register
from ._glslang import GlslangRule


@register
class GlslangWarning(GlslangRule):
    """Finds what glslangValidator warns about in the wrapped file.

    Why is this bad?
        glslang's warnings mark code that some drivers treat differently or not at all (deprecated
        features, extension behaviour).

    Example:
        #extension GL_OES_standard_derivatives : enable

    Fix:
        Remove the directive: derivatives (dFdx, dFdy, fwidth) are core in GLSL ES 3.00.

    Fix safety:
        No fix.

    References:
        - glslang, the Khronos reference front end: https://github.com/KhronosGroup/glslang
        - GLSL ES 3.00 spec §3.4 (Preprocessor: #extension) and §8.9 (Fragment Processing Functions:
          derivatives)
    """

    code = "C002"
    name = "glslang-warning"
    category = "correctness"
    severity = "warning"
    wanted = "warning"
