"""C001 glslang-error."""

from __future__ import annotations

from .. import register
from ._glslang import GlslangRule


@register
class GlslangError(GlslangRule):
    """Finds what the Khronos reference compiler, glslangValidator, rejects, compiled exactly as the
    target wraps the file (ShaderToy: its uniforms before, a `main` after).

    Why is this bad?
        A shader that glslang rejects will not compile in the browser either. The message is placed
        at the line and column of your file, not of the wrapped source. Where a glint rule reports
        an error on the same line (an int where a float belongs, a reserved word), glint's finding,
        with its fix, replaces glslang's.

    Example:
        vec4 c = texture2D(iChannel0, uv);

    Use instead:
        vec4 c = texture(iChannel0, uv);

    Fix safety:
        No fix. glslang's messages carry a hint for the common mistakes; the glint rules that report
        the same mistakes (P003, P004, P005) carry the fixes.

    References:
        - glslang, the Khronos reference front end: https://github.com/KhronosGroup/glslang
        - The OpenGL ES Shading Language 3.00 specification (the language ShaderToy compiles)
        - ShaderToy's How To (https://www.shadertoy.com/howto): the uniforms it declares
    """

    code = "C001"
    name = "glslang-error"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "correctness"
    severity = "error"
    wanted = "error"
