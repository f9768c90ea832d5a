"""The GLSL type algebra (compiler/glsl/types.py), every kind of type, and the places that used
to keep their own copy of it and disagreed: each `test_was_*` fails on one old copy."""

from __future__ import annotations

import numpy as np
import pytest
from lark import Tree

from glint.compiler.catalog_tools.cross import entry_main
from glint.compiler.evaluator import UnsupportedError, evaluate, values
from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import Field, Index, token_text, variable_name
from glint.compiler.glsl.keywords import BUILTIN_TYPES
from glint.compiler.glsl.parser import parse_source
from glint.compiler.glsl.symbols import FunctionDef, Param
from glint.compiler.target.shadertoy import SHADERTOY_TYPES, shadertoy_types
from glint.lint.analysis.expression_types import ExpressionTypes
from glint.lint.analysis.invariance import Program
from glint.lint.analysis.moments import Moments, State
from glint.lint.context import walk

# --- every type -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "element, prefix", [("float", ""), ("int", "i"), ("uint", "u"), ("bool", "b")]
)
def test_scalars_and_vectors_of_every_element_type(element: str, prefix: str) -> None:
    assert T.components(element) == (element, 1)
    assert T.is_scalar(element) and not T.is_vector(element) and T.shape(element) == ()
    for n in (2, 3, 4):
        name = f"{prefix}vec{n}"
        assert name in T.VECTORS and name in BUILTIN_TYPES
        assert T.components(name) == (element, n)
        assert T.size(name) == n and T.is_vector(name) and T.shape(name) == (n,)
        assert T.element_type(name) == element and T.element(name) == element
        assert T.vector(element, n) == name and T.index_count(name) == n
        assert T.is_float_like(name) == (element == "float")
        assert T.is_scalar_constructible(name) and T.constructor(name) == name
    assert T.vector(element, 1) == element


def test_every_matrix_shape_is_columns_then_rows() -> None:
    assert len(T.MATRICES) == 12  # mat2..mat4 and the nine matCxR, three of them equal to matN
    for cols in (2, 3, 4):
        for rows in (2, 3, 4):
            name = f"mat{cols}x{rows}"
            assert T.matrix_shape(name) == (cols, rows) and T.shape(name) == (cols, rows)
            assert T.element(name) == T.vector("float", rows)  # m[i] is a column
            assert T.index_count(name) == cols and T.element_type(name) == "float"
            assert T.size(name) == 0 and not T.is_vector(name) and T.is_float_like(name)
        assert T.matrix_shape(f"mat{cols}") == (cols, cols)
    assert T.matrix(3, 3) == "mat3" and T.matrix(2, 4) == "mat2x4"


@pytest.mark.parametrize(
    "name", ["umat3", "imat2", "bmat4", "mat5", "mat1", "mat2x", "matrix", "material", "uvec",
             "uvec1", "uvec5", "vec", "dvec3", "Vec3", "sampler2DRect", "sampler3DShadow", ""]
)  # fmt: skip
def test_no_type_algebra_for_names_that_are_no_glsl_es_type(name: str) -> None:
    # there are no integer matrices in GLSL ES 3.00: umat3 is a struct name as far as it goes
    assert T.components(name) is None and T.matrix_shape(name) is None
    assert T.sampler(name) is None and T.shape(name) is None and T.element(name) is None
    assert name not in BUILTIN_TYPES and T.size(name) == 0 and not T.is_value(name)
    assert T.constructor(name) == name  # a struct's constructor builds the struct
    assert T.constructor(name, {"S": []}) is None


def test_samplers_every_kind() -> None:
    assert len(T.SAMPLERS) == 15
    assert T.sampler("isampler2DArray") == T.Sampler("int", "2DArray", False)
    assert T.sampler("usamplerCube") == T.Sampler("uint", "Cube", False)
    assert T.sampler("sampler2DArrayShadow") == T.Sampler("float", "2DArray", True)
    assert T.texture_result("usampler3D") == "uvec4"
    assert T.texture_result("isampler2D") == "ivec4"
    assert T.texture_result("samplerCubeShadow") == "float"
    assert T.texture_result(None) == "vec4"
    assert T.texture_size_result("sampler2DArrayShadow") == "ivec3"
    assert T.texture_size_result("samplerCube") == "ivec2"
    assert T.texture_size_result("usampler3D") == "ivec3"
    assert T.constructor("sampler2D") is None and T.constructor("void") is None
    assert not T.is_value("sampler2D") and T.element_type("sampler2D") is None


def test_builtin_types_are_the_lexers_keywords() -> None:
    assert len(BUILTIN_TYPES) == 1 + 4 + 12 + 12 + 15  # void, scalars, vectors, matrices, samplers


def test_arrays() -> None:
    assert T.element("float[4]") == "float" and T.index_count("float[4]") == 4
    assert T.element("vec3[2][3]") == "vec3[3]"  # the first index picks a vec3[3]
    assert T.element("float[]") == "float" and T.index_count("float[]") == 0
    assert T.array_base("vec3[2][3]") == "vec3" and T.is_array("S[2]")
    assert T.constructor("float[3]") == "float[3]" and T.size("float[4]") == 0


# --- swizzles ---------------------------------------------------------------------------------


def test_swizzle_sets_and_sizes() -> None:
    for letters in T.SWIZZLE_SETS:
        assert T.swizzle_indices(letters) == (0, 1, 2, 3)
        assert T.swizzle_indices(letters[2], 2) is None  # .z of a vec2
        assert [T.swizzle_index(c) for c in letters] == [0, 1, 2, 3]
    assert T.swizzle("uvec4", "bgr") == "uvec3" and T.swizzle("bvec2", "yx") == "bvec2"
    assert T.swizzle("ivec3", "p") == "int" and T.swizzle("vec3", "xxxx") == "vec4"
    assert T.swizzle("vec4", "xyzwx") is None  # five letters
    assert T.swizzle("vec3", "xg") is None  # two sets
    assert T.swizzle("mat3", "x") is None and T.swizzle("S", "x") is None
    assert T.swizzle("float", "xx") == "vec2" and T.swizzle("float", "y") is None
    assert T.swizzle_indices("uv") is None and T.swizzle_indices("") is None
    assert T.is_lvalue_swizzle("xz") and not T.is_lvalue_swizzle("xx")


# --- constructors and operators -----------------------------------------------------------


def test_constructor_sources() -> None:
    assert T.constructor_sources("vec3", [1]) == [(0, 0)] * 3  # vec3(x)
    assert T.constructor_sources("uvec3", [2, 1]) == [(0, 0), (0, 1), (1, 0)]
    assert T.constructor_sources("vec2", [4]) == [(0, 0), (0, 1)]  # extra components dropped
    assert T.constructor_sources("vec4", [2, 1]) is None  # too few: an error
    assert T.constructor_sources("float", [3]) == [(0, 0)]
    assert (
        T.constructor_sources("mat2", [1]) is None and T.constructor_sources("vec2", [0, 1]) is None
    )


@pytest.mark.parametrize(
    "op, left, right, result",
    [
        ("+", "vec3", "float", "vec3"), ("*", "float", "uvec2", "uvec2"),
        ("-", "uint", "uint", "uint"), ("<", "float", "float", "bool"),
        ("==", "uvec3", "uvec3", "bool"), ("<<", "uvec2", "int", "uvec2"),
        ("&", "uint", "uvec4", "uvec4"), ("*", "mat3", "vec3", "vec3"),
        ("*", "mat2x3", "vec2", "vec3"), ("*", "vec3", "mat2x3", "vec2"),
        ("*", "mat2x3", "mat4x2", "mat4x3"), ("*", "mat3", "float", "mat3"),
        ("*", "float", "mat2", "mat2"), ("+", "mat2", "float", "mat2"),
        ("+", None, "vec2", "vec2"), ("*", None, "vec2", None), ("/", "float", None, None),
    ],
)  # fmt: skip
def test_binary_result_types(op: str, left: str, right: str, result: str | None) -> None:
    assert T.binary(op, left, right) == result


def test_unary_and_builtin_returns() -> None:
    assert T.unary("!", "bool") == "bool" and T.unary("-", "uvec2") == "uvec2"
    assert T.builtin_return("floatBitsToUint", ["vec3"]) == "uvec3"
    assert T.builtin_return("lessThan", ["uvec2", "uvec2"]) == "bvec2"
    assert T.builtin_return("texelFetch", ["usampler2D", "ivec2", "int"]) == "uvec4"
    assert T.builtin_return("transpose", ["mat2x3"]) == "mat3x2"
    assert T.builtin_return("outerProduct", ["vec3", "vec2"]) == "mat2x3"
    assert T.builtin_return("max", ["float", "vec3"]) == "vec3"
    assert T.builtin_return("nosuch", ["float"]) is None


def test_shadertoy_types() -> None:
    assert SHADERTOY_TYPES["iChannelTime"] == "float[4]"
    assert SHADERTOY_TYPES["iChannelResolution"] == "vec3[4]"
    assert shadertoy_types(["cube", "3d"])["iChannel1"] == "sampler3D"


# --- the old copies' disagreements --------------------------------------------------------


def test_was_an_out_of_range_swizzle_typed_as_a_component() -> None:
    # lint/analysis/types.py typed `v2.z` as a float (its swizzle ignored the vector's size);
    # the evaluator and the flow analysis refused it, as glslang does
    tree, _ = parse_source("float f(vec2 v) { return v.z + v.y; }")
    types = ExpressionTypes(tree)
    fields = {_key(n): types.type_of(n) for n in walk(tree) if Field.cast(n) is not None}
    assert fields == {"v.z": None, "v.y": "float"}


def _key(node: Tree) -> str | None:
    field, index = Field.cast(node), Index.cast(node)
    if field is not None:
        return f"{variable_name(field.base)}.{field.name}"
    if index is not None:
        return f"{variable_name(index.base)}[{token_text(index.index)}]"
    return None


def _moment(source: str, wanted: str) -> str | None:
    """The type the moments give the expression `wanted` (`V.xy`, `U[1]`) of the source."""
    tree, _ = parse_source(source)
    moments = Moments(tree)
    node = next(n for n in walk(tree) if _key(n) == wanted)
    return moments.expr(node, State(moments.globals)).type


MOMENT_SRC = """
const uvec3 U = uvec3(1u, 2u, 3u);
const vec3 V = vec3(1.0, 2.0, 3.0);
const float A[2][3] = float[2][3](float[3](1.0, 2.0, 3.0), float[3](4.0, 5.0, 6.0));
void mainImage(out vec4 c, in vec2 p) { c = vec4(U.xy, U[1], V.xg, V.x); }
"""


def test_was_a_uvec_swizzle_an_ivec_in_the_moments() -> None:
    # moments.py's base_of held uint as int and named the swizzle after it: U.xy was an ivec2
    assert _moment(MOMENT_SRC, "U.xy") == "uvec2"
    assert _moment(MOMENT_SRC, "U[1]") == "uint"


def test_was_a_swizzle_mixing_two_sets_followed_by_the_moments() -> None:
    # moments.py read each letter on its own (swizzle_index), so V.xg was vec2(1, 2)
    assert _moment(MOMENT_SRC, "V.xg") is None
    assert _moment(MOMENT_SRC, "V.x") == "float"


def test_was_a_name_starting_mat_a_matrix_in_the_evaluator() -> None:
    # the evaluator's is_matrix was `startswith("mat")`: an unknown type `matrix` crashed it
    # (int("rix")) instead of being reported as unsupported; a struct `material` still works
    with pytest.raises(UnsupportedError, match="type 'matrix' is not supported"):
        evaluate("float f(float x) { matrix m; return x; }", "f", [np.array([1.0])])
    src = """
    struct material { float rough; };
    float f(float x) { material m = material(x); return m.rough * 2.0; }"""
    out = evaluate(src, "f", [np.array([1.0, 2.0])])
    np.testing.assert_allclose(np.asarray(out), [2.0, 4.0])


def test_was_a_uvec_a_float_scalar_to_the_evaluator() -> None:
    # the evaluator's own copy knew no uvec: base_of("uvec3") was float, vec_size 1
    assert values.base_of("uvec3") == "uint" and values.vec_size("uvec3") == 3
    assert not values.is_value_type("uvec3")  # it computes with no unsigned values (yet)
    assert values.component_dims("mat2x3") == 2 and values.mat_shape("mat4x2") == (4, 2)


def test_was_matrix_comp_mult_a_free_constructor_in_the_cost_model() -> None:
    # invariance.py took any name starting "mat" for a constructor, costing nothing
    tree, _ = parse_source("mat2 f(mat2 a) { return matrixCompMult(a, a); }")
    call = next(n for n in walk(tree) if isinstance(n, Tree) and n.data == "call")
    program = Program(ctx=None, overloads={}, globals=set(), trips=None)  # type: ignore[arg-type]
    assert program.cost(call, None) >= 1
    ctor = next(
        n
        for n in walk(parse_source("vec2 g() { return vec2(1.0); }")[0])
        if n.data == "constructor"
    )
    assert program.cost(ctor, None) == 0


def test_was_a_non_square_matrix_argument_left_unset_by_cross_compilation() -> None:
    # catalog_cross built mat2/mat3/mat4 arguments from x but not matCxR ones, which GLSL
    # constructs alike (x on the diagonal)
    fn = FunctionDef(
        name="g", params=[Param("", "mat2x3", "m"), Param("", "uvec2", "u")], return_type="mat2x3",
        prototype="mat2x3 g(mat2x3 m, uvec2 u)", line=1, end_line=1,
    )  # fmt: skip
    text = entry_main([fn])
    assert "mat2x3 arg0 = mat2x3(x);" in text and "uvec2 arg1 = uvec2(x);" in text
    assert "g(arg0, arg1);" in text  # a matrix result: the call alone keeps the function
