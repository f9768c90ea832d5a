"""C002 glslang-warning."""

from __future__ import annotations

from .. import register
from ._glslang import GlslangRule


@register
class GlslangWarning(GlslangRule):
    """Finds what glslangValidator warns about in the wrapped file.

    Why it matters: glslang's warnings mark code that some drivers treat differently or not at
    all (deprecated features, extension behaviour).

    Example:
        #extension GL_OES_standard_derivatives : enable

    Fix:
        remove the directive: derivatives are core in GLSL ES 3.00.
    """

    code = "C002"
    name = "glslang-warning"
    category = "correctness"
    severity = "warning"
    wanted = "warning"
