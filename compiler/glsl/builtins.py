"""Names GLSL ES 3.00 provides, which a module therefore never has to define. What a target adds
(ShaderToy's uniforms) is the target's to say: see `symbols_of(..., provided=...)`."""

from __future__ import annotations

from glint.compiler.glsl.keywords import BUILTIN_TYPES, QUALIFIER_GROUPS, words

# Section 8 of the GLSL ES 3.00 spec, in its order: angle/trig, exponential, common,
# floating-point packing, geometric, matrix, vector relational, texture, derivatives.
BUILTIN_FUNCTIONS: frozenset[str] = words(
    """
    radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh
    pow exp log exp2 log2 sqrt inversesqrt
    abs sign floor trunc round roundEven ceil fract mod modf min max clamp mix step smoothstep
    isnan isinf floatBitsToInt floatBitsToUint intBitsToFloat uintBitsToFloat
    packSnorm2x16 unpackSnorm2x16 packUnorm2x16 unpackUnorm2x16 packHalf2x16 unpackHalf2x16
    length distance dot cross normalize faceforward reflect refract
    matrixCompMult outerProduct transpose determinant inverse
    lessThan lessThanEqual greaterThan greaterThanEqual equal notEqual any all not
    textureSize texture textureProj textureLod textureOffset texelFetch texelFetchOffset
    textureProjOffset textureLodOffset textureProjLod textureProjLodOffset textureGrad
    textureGradOffset textureProjGrad textureProjGradOffset
    dFdx dFdy fwidth
    """
)

# Fragment-stage variables and constants; every `gl_` name is reserved anyway.
BUILTIN_VARIABLES: frozenset[str] = words(
    """
    gl_FragCoord gl_FrontFacing gl_PointCoord gl_FragDepth gl_FragColor gl_FragData
    gl_DepthRange gl_MaxVertexAttribs gl_MaxVertexUniformVectors gl_MaxVertexOutputVectors
    gl_MaxFragmentInputVectors gl_MaxVertexTextureImageUnits gl_MaxCombinedTextureImageUnits
    gl_MaxTextureImageUnits gl_MaxFragmentUniformVectors gl_MaxDrawBuffers
    gl_MinProgramTexelOffset gl_MaxProgramTexelOffset
    """
)

# Words that can appear in macro bodies but are never user symbols.
LANGUAGE_WORDS: frozenset[str] = (
    words(
        """
        if else for while do switch case default break continue return discard struct
        precision layout invariant true false
        """
    )
    | BUILTIN_TYPES
    | frozenset(QUALIFIER_GROUPS)
)


def is_builtin(name: str) -> bool:
    """Whether `name` is provided by GLSL ES 3.00 rather than by user code."""
    return (
        name in BUILTIN_FUNCTIONS
        or name in BUILTIN_VARIABLES
        or name in LANGUAGE_WORDS
        or name.startswith("gl_")
        or name in ("__LINE__", "__FILE__", "__VERSION__", "GL_ES", "GL_FRAGMENT_PRECISION_HIGH")
    )
