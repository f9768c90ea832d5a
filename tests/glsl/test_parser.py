"""Parser: precedence, statements, types, errors."""

from __future__ import annotations

import pytest
from lark import Token, Tree

from glint.compiler.glsl.parser import GLSLSyntaxError, parse, parse_source


def expr(text: str) -> Tree:
    """The tree of one expression, parsed as a global initializer."""
    tree = parse(f"float _x = {text};")
    decl = tree.children[0].children[1]
    return decl.children[1]


def sexp(node: Tree | Token) -> str:
    """A compact prefix form that makes grouping visible: (+ a (* b c))."""
    if isinstance(node, Token):
        return str(node)
    kids = node.children
    if node.data in ("binary", "assignment"):
        return f"({kids[1]} {sexp(kids[0])} {sexp(kids[2])})"
    if node.data in ("unary", "prefix"):
        return f"({kids[0]} {sexp(kids[1])})"
    if node.data == "postfix":
        return f"(post{kids[1]} {sexp(kids[0])})"
    if node.data == "ternary":
        return f"(? {' '.join(sexp(k) for k in kids)})"
    if node.data in ("variable", "int_literal", "float_literal", "bool_literal"):
        return str(kids[0])
    return f"({node.data} {' '.join(sexp(k) for k in kids)})"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a + b * c", "(+ a (* b c))"),
        ("a - b - c", "(- (- a b) c)"),
        ("a / b % c", "(% (/ a b) c)"),
        ("a << 1 + b", "(<< a (+ 1 b))"),
        ("a < b == c > d", "(== (< a b) (> c d))"),
        ("a & b ^ c | d", "(| (^ (& a b) c) d)"),
        ("a == b & c", "(& (== a b) c)"),
        ("a || b ^^ c && d", "(|| a (^^ b (&& c d)))"),
        ("a ? b : c ? d : e", "(? a b (? c d e))"),
        ("a || b ? c : d", "(? (|| a b) c d)"),
        ("-a * b", "(* (- a) b)"),
        ("!a && ~b == c", "(&& (! a) (== (~ b) c))"),
        ("-a++", "(- (post++ a))"),
        ("++a.x", "(++ (field a x))"),
        ("a.xy[1] * 2.0", "(* (index (field a xy) 1) 2.0)"),
        ("f(a, b)(c)", "(call (call f (arguments a b)) (arguments c))"),
    ],
)
def test_precedence_and_associativity(text: str, expected: str) -> None:
    assert sexp(expr(text)) == expected


def test_assignment_is_right_associative_with_all_operators() -> None:
    ops = ["=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "^=", "|="]
    for op in ops:
        tree = parse(f"void f() {{ a {op} b = c; }}")
        stmt = next(tree.find_data("expression_statement")).children[0]
        assert sexp(stmt) == f"({op} a (= b c))"


def test_comma_sequence_in_for_update() -> None:
    tree = parse("void f() { for (int i = 0, j = 1; i < 3; i++, j--) {} }")
    assert next(tree.find_data("sequence")) is not None


def test_every_statement_kind() -> None:
    src = """
    void f(int k) {
        int a = 0;
        ;
        { a++; }
        if (a > 0) a--; else { a = 1; }
        if (a > 0) if (k > 0) a = 2; else a = 3;
        while (a < 10) a++;
        while (bool go = a < 3) { a++; }
        do { a--; } while (a > 0);
        for (;;) { break; }
        for (a = 0; a < 3; a++) continue;
        switch (k) { case 0: case 1: a = 1; break; default: a = 2; }
        if (a == 7) discard;
        return;
    }
    """
    tree = parse(src)
    kinds = {t.data for t in tree.iter_subtrees()}
    for kind in [
        "declaration_statement", "empty_statement", "compound_statement", "if_statement",
        "while_statement", "condition_declaration", "do_statement", "for_statement",
        "switch_statement", "case_label", "default_label", "jump_statement",
    ]:  # fmt: skip
        assert kind in kinds, kind


def test_dangling_else_binds_to_inner_if() -> None:
    tree = parse("void f() { if (a) if (b) x(); else y(); }")
    ifs = {str(t.children[0].children[0]): t for t in tree.find_data("if_statement")}
    assert len(ifs["a"].children) == 2  # condition and the inner if; the else went inside
    assert len(ifs["b"].children) == 3


def test_struct_names_become_types() -> None:
    tree = parse(
        "struct S { float a, b[2]; vec3 c; }; S s;\n"
        "S make() { S t = S(1.0, float[2](1.,2.), vec3(0)); return t; }"
    )
    names = [t for t in tree.scan_values(lambda v: isinstance(v, Token) and v.type == "TYPE_NAME")]
    assert [str(n) for n in names] == ["S", "S", "S", "S"]


def test_struct_with_declarator_and_arrays() -> None:
    tree = parse(
        "struct L { vec3 d; } sun, moons[2]; float a[3], b = 1.0;\n"
        "float[3] c; float[] d = float[](1.,2.);"
    )
    decls = list(tree.find_data("declarator"))
    assert [str(d.children[0]) for d in decls] == ["sun", "moons", "a", "b", "c", "d"]


def test_qualifiers_precision_layout_and_blocks() -> None:
    src = """
    precision highp float;
    precision mediump sampler3D;
    uniform vec3 iResolution;
    uniform float iChannelTime[4];
    layout(location = 0) out highp vec4 color;
    flat in int id;
    smooth centroid in vec2 uv;
    invariant gl_FragCoord;
    uniform Block { mat4 m; vec4 v; } blk;
    const highp float K = 1.0;
    void f(const in float a, inout vec2 b, out float c[2]) {}
    """
    tree = parse(src)
    assert len(tree.children) == 11


def test_literals() -> None:
    kinds = [t.data for t in parse(
        "float a[11] = float[](1., .5, 1e-3, 1.0e+5, 2.f, 3.F, 1, 0x1F, 017, 3u, 0xFFu);"
    ).find_data("float_literal")]  # fmt: skip
    assert len(kinds) == 6
    assert len(list(parse("bool t = true || false;").find_data("bool_literal"))) == 2


def test_constructors_for_builtin_types() -> None:
    types = ["mat2x3", "mat4", "ivec2", "uvec4", "bvec3", "uint", "bool", "float[3]", "float[]"]
    for ty in types:
        tree = parse(f"void f() {{ x = {ty}(1); }}")
        assert next(tree.find_data("constructor"))


def test_positions_on_nodes() -> None:
    tree = parse("\n\nfloat f() {\n  return 1.0 +\n    2.0;\n}\n")
    ret = next(tree.find_data("jump_statement"))
    assert (ret.meta.line, ret.meta.column, ret.meta.end_line) == (4, 3, 5)


@pytest.mark.parametrize(
    ("source", "line", "column", "fragment"),
    [
        ("float x = 1.0\nfloat y;", 2, 1, "unexpected 'float'"),
        ("void f() { g(1, ; }", 1, 17, "unexpected ';'"),
        ("void f() {", 1, 11, "unexpected end of input"),
        ("float class;", 1, 7, "'class' is a reserved word"),
        ("float a = 1 $ 2;", 1, 13, "unexpected character '$'"),
    ],
)
def test_syntax_errors(source: str, line: int, column: int, fragment: str) -> None:
    with pytest.raises(GLSLSyntaxError) as info:
        parse(source, "x.glsl")
    err = info.value
    assert (err.file, err.line, err.column) == ("x.glsl", line, column)
    assert fragment in err.message
    assert err.message.startswith(f"x.glsl:{line}:{column}: syntax error: ")


def test_expected_list_is_short() -> None:
    with pytest.raises(GLSLSyntaxError) as info:
        parse("void f() { x = (1 + 2; }")
    assert info.value.message.endswith("expected one of ')', ','")


def test_parse_source_maps_errors_to_original_lines() -> None:
    src = '#define A 1\n/* two\n lines */\n#line 40 "snippet.glsl"\nfloat x = A\nint y;'
    with pytest.raises(GLSLSyntaxError) as info:
        parse_source(src, "main.glsl")
    assert (info.value.file, info.value.line) == ("snippet.glsl", 41)


def test_parse_source_returns_tree_and_preprocessed() -> None:
    tree, pre = parse_source("#version 300 es\nfloat x = 1.0;")
    assert pre.version == "300 es"
    assert tree.data == "start"


def token_types(tree: Tree, name: str) -> list[str]:
    """The token type of every occurrence of `name`, in source order."""
    return [t.type for t in tree.scan_values(lambda v: isinstance(v, Token) and v == name)]


def test_struct_member_may_share_its_types_name() -> None:
    tree = parse(
        "struct ray { vec3 o; };\n"
        "struct camera { ray ray; ray other; };\n"
        "float f(camera c) { return c.ray.o.x; }"
    )
    kinds = ["IDENTIFIER", "TYPE_NAME", "IDENTIFIER", "TYPE_NAME", "IDENTIFIER"]
    assert token_types(tree, "ray") == kinds


def test_local_variable_hides_a_type_after_its_initializer() -> None:
    tree = parse(
        "struct ray { vec3 o; };\n"
        "float f() { ray ray = ray(vec3(1)); ray.o.x += 1.0; return ray.o.x; }\n"
        "ray g() { ray r; return r; }"
    )
    assert token_types(tree, "ray") == [
        "IDENTIFIER",  # struct ray
        "TYPE_NAME", "IDENTIFIER", "TYPE_NAME",  # ray ray = ray(...): the type until the `;`
        "IDENTIFIER", "IDENTIFIER",  # the variable
        "TYPE_NAME", "TYPE_NAME",  # the type again in the next function
    ]  # fmt: skip
    assert len(list(tree.find_data("constructor"))) == 2  # ray(...) and vec3(...)


def test_parameter_and_for_variable_hide_a_type_in_their_body() -> None:
    tree = parse(
        "struct ray { vec3 o; };\n"
        "float f(ray ray) { return ray.o.x; }\n"
        "float g(vec3 ray);\n"
        "float h() {\n"
        "  for (ray ray = ray(vec3(0)); ray.o.x < 1.0; ray.o.x += 0.1) { ray.o.y = 1.0; }\n"
        "  ray r; return r.o.x;\n"
        "}"
    )
    assert token_types(tree, "ray") == [
        "IDENTIFIER",  # struct ray
        "TYPE_NAME", "IDENTIFIER", "IDENTIFIER",  # f(ray ray) { ray.o.x }
        "IDENTIFIER",  # g(vec3 ray): the prototype's name does not outlive it
        "TYPE_NAME", "IDENTIFIER", "TYPE_NAME", "IDENTIFIER", "IDENTIFIER", "IDENTIFIER",
        "TYPE_NAME",  # after the loop, the type again
    ]  # fmt: skip


def test_struct_names_are_block_scoped() -> None:
    tree = parse(
        "float f() { { struct Hit { float t; }; Hit h; h.t = 1.0; }\n"
        "  float Hit = 2.0; return Hit; }\n"
        "float g() { float Hit = 3.0; return Hit * 2.0; }"
    )
    kinds = ["IDENTIFIER", "TYPE_NAME"] + ["IDENTIFIER"] * 4
    assert token_types(tree, "Hit") == kinds


def test_declarators_after_a_struct_and_in_lists_are_identifiers() -> None:
    tree = parse("struct ray { vec3 o; } a, b[2];\nfloat f() { return a.o.x + b[1].o.x; }")
    assert [str(d.children[0]) for d in tree.find_data("declarator")] == ["a", "b"]


@pytest.mark.parametrize(
    "source",
    [
        "T[2] a;",
        "T a[2];",
        "T[2][3] a;",
        "float f() { T[2] a; T b[3]; T[N + 1] c; return a[0].x + b[1].x; }",
        "float f(T[2] a, in T b[2]) { return 1.0; }",
        "struct S { T[2] m; U n; };",
        "T[2] make();",
    ],
)
def test_a_type_declared_elsewhere_in_an_array_declaration(source: str) -> None:
    tree = parse(source)
    assert "T" in set(tree.scan_values(lambda v: isinstance(v, Token) and v.type == "TYPE_NAME"))


def test_indexing_an_undeclared_name_stays_an_expression() -> None:
    tree = parse("void f() { x[2] = 1.0; y[i][j] += g[k](1.0); }")
    assert not list(tree.scan_values(lambda v: isinstance(v, Token) and v.type == "TYPE_NAME"))


@pytest.mark.parametrize(
    "source",
    [
        "float f(vec3, float b);",
        "float f(vec3, float b) { return b; }",
        "float f(in vec3, out float[2], const int) { return 1.0; }",
        "struct S { float x; }; float f(S, S s) { return s.x; }",
        "float f(T, inout U) { return 1.0; }",  # types declared in another snippet
        "void f(void) {}",
    ],
)
def test_unnamed_parameters(source: str) -> None:
    parse(source)


def test_names_with_double_underscores_are_allowed() -> None:
    # reserved for the implementation, but in ES 3.00 using one is not an error (spec §3.7)
    parse("float a__b = 1.0;\nfloat f(float __x) { return __x * a__b; }")
