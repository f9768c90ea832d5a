"""Preprocessor: macros, conditionals, line map and error positions."""

from __future__ import annotations

import pytest

from glint.compiler.glsl.preprocessor import PreprocessorError, SourceLocation, preprocess


def lines(source: str, **kwargs: object) -> list[str]:
    return [line.strip() for line in preprocess(source, **kwargs).text.split("\n")]  # type: ignore[arg-type]


def squash(text: str) -> str:
    return "".join(text.split())


def test_output_keeps_one_line_per_input_line() -> None:
    src = "#define A 1\n/* a\n comment */ float x = A;\n// only a comment\nfloat y;\n"
    out = preprocess(src)
    assert len(out.text.split("\n")) == len(src.split("\n"))
    assert lines(src)[2] == "float x =  1 ;"
    assert out.line_map[2] == SourceLocation("<input>", 3)


def test_comments_keep_columns() -> None:
    assert preprocess("/* c */ float x;").text == "        float x;"


def test_object_macro_and_rescan() -> None:
    src = "#define PI 3.14\n#define TAU (2.0 * PI)\nfloat t = TAU;"
    assert squash(lines(src)[2]) == "floatt=(2.0*3.14);"


def test_function_like_macro_with_nested_arguments() -> None:
    src = "#define SQ(x) ((x)*(x))\n#define ADD(a, b) (a + b)\nfloat y = SQ(ADD(f(1, 2), 3.0));"
    assert squash(lines(src)[2]) == "floaty=(((f(1,2)+3.0))*((f(1,2)+3.0)));"


@pytest.mark.parametrize(
    ("source", "expanded", "fused"),
    [
        # `(a-b)` with b = `-1.` is a minus and a negative number, not a decrement
        ("#define O(a,b) (a-b)+b\nfloat v = O(1.1, -1.);", "(1.1- -1.)+-1.", "--"),
        ("#define P(a) x+a\nfloat v = P(+y);", "x+ +y", "++"),
        ("#define A(x) x\nfloat v = A(a)A(b);", "a b", "ab"),
        ("#define S(x) -x\nfloat v = 3-S(2);", "3- -2", "--"),
        ("#define L(x) x<\nbool v = L(a)=b;", "a< =b", "<="),
    ],
)
def test_expanded_tokens_never_fuse_with_their_neighbours(
    source: str, expanded: str, fused: str
) -> None:
    """The preprocessor works on tokens: an expansion that would otherwise put `-` before `-1.`
    or two names side by side keeps them apart (glslang reads them so)."""
    line = lines(source)[1]
    assert fused not in line and expanded in " ".join(line.split())


def test_function_like_macro_name_without_call_is_left_alone() -> None:
    assert squash(lines("#define F(x) x\nfloat F = 1.0;")[1]) == "floatF=1.0;"


def test_no_recursive_self_expansion() -> None:
    src = "#define foo foo + 1\n#define A B\n#define B A\nint x = foo; int y = A;"
    assert squash(lines(src)[3]) == "intx=foo+1;inty=A;"


def test_token_pasting() -> None:
    src = "#define CAT(a, b) a ## b\n#define V 3\nvec3 CAT(my, Var) = vec CAT(V, );"
    assert squash(lines(src)[2]) == "vec3myVar=vec3;"  # the pasted V is rescanned


def test_macro_call_across_lines_maps_to_first_line() -> None:
    src = "#define SUM(a, b) (a + b)\nfloat s = SUM(1.0,\n   2.0);\nfloat t;"
    out = preprocess(src)
    text = out.text.split("\n")
    assert squash(text[1]) == "floats=(1.0+2.0);"
    assert text[2] == ""
    assert out.line_map[3] == SourceLocation("<input>", 4)


def test_line_continuation() -> None:
    src = "#define LONG 1.0 + \\\n  2.0\nfloat x = LONG;"
    assert squash(lines(src)[2]) == "floatx=1.0+2.0;"


def test_nested_conditionals() -> None:
    src = """#define A 2
#if A > 1
#  ifdef B
int wrong1;
#  elif defined(A) && !defined B
int right;
#  else
int wrong2;
#  endif
#else
#  if 1
int wrong3;
#  endif
#endif"""
    kept = [line for line in lines(src) if line]
    assert kept == ["int right;"]


def test_skipped_branches_ignore_bad_directives() -> None:
    assert lines("#if 0\n#frobnicate\n#error no\n#endif\nint x;")[4] == "int x;"


@pytest.mark.parametrize(
    ("expr", "value"),
    [
        ("1 + 2 * 3 == 7", True),
        ("(1 + 2) * 3 == 7", False),
        ("0x10 == 16 && 010 == 8", True),
        ("1 << 4 == 16", True),
        ("-3 / 2 == -1 && -3 % 2 == -1", True),
        ("~0 == -1", True),
        ("3 > 2 > 1", False),  # (3 > 2) > 1 is 1 > 1
        ("!defined(X) && defined GL_ES", True),
        ("__VERSION__ == 300 && GL_ES", True),
        # `&&` and `||` short-circuit: an operand that is not evaluated may name anything
        ("defined(X) && X > 1", False),
        ("!defined(X) || X > 1", True),
        ("0 && (X + Y * 2)", False),
        ("1 || X", True),
        ("1 || X && Y", True),
        ("0 && X || 1", True),
        ("0 && 1 / 0", False),
        ("1 || 1 % 0", True),
        ("defined X && X", False),
    ],
)
def test_if_expressions(expr: str, value: bool) -> None:
    out = lines(f"#if {expr}\nint yes;\n#endif")
    assert (out[1] == "int yes;") is value


def test_predefined_macros_and_override() -> None:
    assert squash(lines("int v = __VERSION__;")[0]) == "intv=300;"
    assert squash(lines("float q = Q;", predefined={"Q": "2.0"})[0]) == "floatq=2.0;"
    assert squash(lines("int v = GL_ES;", predefined={"GL_ES": "0"})[0]) == "intv=0;"


def test_line_directive_changes_map_and_line_macro() -> None:
    out = preprocess('int a;\n#line 100 "snippet.glsl"\nint b = __LINE__;\nint c;')
    assert out.line_map[2] == SourceLocation("snippet.glsl", 100)
    assert out.line_map[3] == SourceLocation("snippet.glsl", 101)
    assert squash(out.text.split("\n")[2]) == "intb=100;"


def test_version_extension_pragma_and_defines() -> None:
    src = "#version 300 es\n#extension GL_EXT_foo : enable\n#pragma optimize(on)\n#\n#define K 1"
    out = preprocess(src, filename="a.glsl")
    assert out.version == "300 es"
    assert out.extensions == ["GL_EXT_foo"]
    assert out.defines["K"].body == "1"
    assert out.defines["K"].params is None
    assert (out.defines["K"].file, out.defines["K"].line) == ("a.glsl", 5)


def test_undef() -> None:
    assert lines("#define A 1\n#undef A\nint x = A;")[2] == "int x = A;"


def test_expansions_are_recorded_per_line() -> None:
    out = preprocess("#define A B\n#define B 1\nint x = A;\nint y;")
    assert out.expansions == {3: {"A", "B"}}


@pytest.mark.parametrize(
    ("source", "line", "column", "fragment"),
    [
        ("int a;\n#error stop here", 2, 2, "#error stop here"),
        ("int a;\n  #frob", 2, 4, "unknown preprocessor directive '#frob'"),
        ("#if 1\nint a;\n", 1, 2, "unterminated #if"),
        ("#endif", 1, 2, "#endif without #if"),
        ("#if 1\n#else\n#elif 1\n#endif", 3, 2, "#elif after #else"),
        ("#define F(a) a\nint x = F(1, 2);", 2, 9, "takes 1 argument"),
        ("#define F(a) a\nint x = F(1;", 2, 10, "unterminated macro call"),
        ("\n#if UNDEFINED_THING\n#endif", 2, 5, "undefined macro 'UNDEFINED_THING'"),
        ("#if 1 / 0\n#endif", 1, 7, "division by zero"),
        ("#if 1 && X\n#endif", 1, 10, "undefined macro 'X'"),
        ("#if 0 || X\n#endif", 1, 10, "undefined macro 'X'"),
        ("#if (0 && X) || Y\n#endif", 1, 17, "undefined macro 'Y'"),
        ("#if 0\n#elif defined(A) || B\n#endif", 2, 21, "undefined macro 'B'"),
        ("#if 1 ? 1 : 0\n#endif", 1, 7, "unexpected '?'"),
        ("#define A 1\n#define A 2", 2, 2, "redefined"),
        ("#define GL_X 1", 1, 2, "reserved"),
        ("int a; /* open\n", 1, 8, "unterminated comment"),
        ("int a;\n#version 300 es", 2, 2, "#version must come first"),
        ('#line 10 "f.glsl"\n#error here', 10, 2, "f.glsl:10:2"),
    ],
)
def test_errors_have_positions(source: str, line: int, column: int, fragment: str) -> None:
    with pytest.raises(PreprocessorError) as info:
        preprocess(source, filename="s.glsl")
    err = info.value
    assert (err.line, err.column) == (line, column)
    assert fragment in err.message
    assert err.message.startswith(f"{err.file}:{line}:{column}: ")
    assert err.exit_code == 1


# --- runaway macros: stopped early, with the macro named -------------------------------------


def _chain(levels: int, body: str) -> str:
    """`#define A0 x` and each next macro built from the one before; A<levels-1> used."""
    lines = ["#define A0 x"] + [
        f"#define A{i} {body.format(p=f'A{i - 1}')}" for i in range(1, levels)
    ]
    return "\n".join(lines) + f"\nfloat y = A{levels - 1};\n"


def test_hide_sets_are_shared_by_the_tokens_of_an_expansion() -> None:
    # Each token held a copy of its hide set: a chain of a thousand macros took gigabytes.
    from glint.compiler.glsl.macros import Expander, Macro
    from glint.compiler.glsl.pptokens import tokenize

    macros = {"A": Macro.make("A", None, "B B B", "<t>", 1), "B": Macro.make("B", None, "x", "", 2)}
    out = Expander(macros, lambda: 1).expand(tokenize("A A"))
    xs = [t for t in out if t.text == "x"]
    assert len(xs) == 6 and len({id(t.hide) for t in xs}) == 1, [t.hide for t in xs]


@pytest.mark.parametrize(
    ("body", "fragment"),
    [
        ("{p}+{p}", "expanding 'A999'"),  # doubles at every level
        ("{p} {p}", "expanding 'A999'"),
        ("({p}+1)", "expanding 'A999' expands macros inside macros more than 256 levels deep"),
    ],
)
def test_a_chain_of_a_thousand_macros_is_an_error_naming_the_macro(
    body: str, fragment: str
) -> None:
    with pytest.raises(PreprocessorError, match="nested too deeply") as raised:
        preprocess(_chain(1000, body), "chain.glsl")
    assert fragment in raised.value.what
    assert raised.value.line == 1001


def test_a_doubling_macro_is_stopped_at_the_expansion_limit() -> None:
    with pytest.raises(PreprocessorError, match="expanding 'A30' takes this file's macro expan"):
        preprocess(_chain(31, "{p}+{p}"), "bomb.glsl")


def test_macros_nested_within_the_limits_expand() -> None:
    result = preprocess(_chain(200, "({p}+1)"), "deep.glsl")
    expanded = result.text.splitlines()[-1].replace(" ", "")
    assert expanded == "floaty=" + "(" * 199 + "x" + "+1)" * 199 + ";"


def test_lenient_takes_an_undefined_name_in_if_as_zero_and_keeps_the_problem() -> None:
    # a ShaderToy pass testing a macro its Common tab defines: the linter reads on
    src = "#if CACHE > 0\nint a;\n#else\nint b;\n#endif\n#if defined(X) && X\nint c;\n#endif\n"
    result = preprocess(src, "pass.glsl", lenient=True)
    assert "int b;" in result.text and "int a;" not in result.text
    assert [(p.line, p.column, p.what) for p in result.problems] == [
        (1, 5, "#if: undefined macro 'CACHE' in expression")
    ]
    with pytest.raises(PreprocessorError, match="undefined macro 'CACHE'"):
        preprocess(src, "pass.glsl")  # strict for the compiler
    with pytest.raises(PreprocessorError, match="missing #endif"):
        preprocess("#if A\n", "pass.glsl", lenient=True)  # only the undefined name is let go
