"""GLSL ES 3.00 words the lexer must know: builtin types, grouped qualifiers, reserved words."""

from __future__ import annotations

# Every type named by a keyword (the lexer's TYPE_NAME) is the type algebra's to say.
from glint.compiler.glsl.types import BUILTIN_TYPES as BUILTIN_TYPES


def words(text: str) -> frozenset[str]:
    """A set of whitespace-separated words (long keyword lists read better as text)."""
    return frozenset(text.split())


# Qualifiers that the grammar takes as one terminal per group (see glsl.lark).
QUALIFIER_GROUPS: dict[str, str] = {
    **dict.fromkeys(("const", "in", "out", "inout", "uniform", "centroid"), "STORAGE_QUALIFIER"),
    **dict.fromkeys(("highp", "mediump", "lowp"), "PRECISION_QUALIFIER"),
    **dict.fromkeys(("smooth", "flat"), "INTERPOLATION_QUALIFIER"),
}

# Section 3.8 of the ES 3.00 spec: reserved for future use, an error to use as a name.
RESERVED_WORDS: frozenset[str] = words(
    """attribute varying coherent volatile restrict readonly writeonly resource atomic_uint
    noperspective patch sample subroutine common partition active asm class union enum typedef
    template this goto inline noinline public static extern external interface long short
    double half fixed unsigned superp input output hvec2 hvec3 hvec4 dvec2 dvec3 dvec4 fvec2
    fvec3 fvec4 sampler3DRect filter image1D image2D image3D imageCube iimage1D iimage2D
    iimage3D iimageCube uimage1D uimage2D uimage3D uimageCube image1DArray image2DArray
    iimage1DArray iimage2DArray uimage1DArray uimage2DArray imageBuffer iimageBuffer
    uimageBuffer sampler1D sampler1DShadow sampler1DArray sampler1DArrayShadow isampler1D
    isampler1DArray usampler1D usampler1DArray sampler2DRect sampler2DRectShadow
    isampler2DRect usampler2DRect samplerBuffer isamplerBuffer usamplerBuffer sampler2DMS
    isampler2DMS usampler2DMS sampler2DMSArray isampler2DMSArray usampler2DMSArray sizeof cast
    namespace using"""
)
