"""The typed syntax layer (compiler/glsl/ast.py): a view for every node kind the parser builds,
properties that read back the parts of small snippets, the for statement's optional parts kept
exactly, and no positional `children[i]` outside the front end but in the modules not yet
converted (a list that may only shrink)."""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from lark import Token, Tree

from glint.compiler.errors import InputError
from glint.compiler.evaluator.api import evaluate
from glint.compiler.glsl import ast, parse, preprocess
from glint.compiler.glsl.ast import (
    VIEWS,
    Assignment,
    Binary,
    BlockDeclaration,
    BoolLiteral,
    Call,
    CaseLabel,
    CompoundStatement,
    ConditionDeclaration,
    Constructor,
    DeclarationStatement,
    Declarator,
    DoStatement,
    ExpressionStatement,
    Field,
    FloatLiteral,
    ForStatement,
    FunctionDefinition,
    FunctionPrototype,
    IfStatement,
    Index,
    IntLiteral,
    JumpStatement,
    Postfix,
    PrecisionDeclaration,
    Prefix,
    Sequence,
    StructSpecifier,
    SwitchStatement,
    Ternary,
    Unary,
    Variable,
    VariableDeclaration,
    View,
    WhileStatement,
    for_parts,
    view,
)

ROOT = Path(__file__).resolve().parents[2]
SHADERS = ROOT.parent / "shared" / "corpus" / "shadertoy"


def _tree(source: str) -> Tree:
    return parse(preprocess(source, "t.glsl").text, "t.glsl")


def _nodes(tree: Tree) -> Iterator[Tree]:
    stack: list[Tree | Token] = [tree]
    while stack:
        item = stack.pop()
        if isinstance(item, Tree):
            yield item
            stack.extend(reversed(item.children))  # in source order


def _first(source: str, kind: str) -> Tree:
    return next(n for n in _nodes(_tree(source)) if n.data == kind)


def _in_main(body: str, kind: str) -> Tree:
    return _first("void f() {\n" + body + "\n}\n", kind)


def _text(node: object) -> str:
    """The tokens under a node, joined: enough to say which part a property gave."""
    if isinstance(node, Token):
        return str(node)
    if isinstance(node, View):
        node = node.syntax
    assert isinstance(node, Tree), node
    return " ".join(_text(c) for c in node.children)


def _read_every_property(node: Tree) -> None:
    found = view(node)
    assert found is not None, f"no view for '{node.data}'"
    for cls in type(found).__mro__:
        for name, attribute in vars(cls).items():
            if isinstance(attribute, property):
                getattr(found, name)


# --- every node kind has a view ---------------------------------------------------------------


def _corpus_files() -> list[Path]:
    files = sorted((ROOT / "tests" / "corpus").rglob("*.glsl"))
    if SHADERS.is_dir():
        files += sorted(SHADERS.glob("*.glsl"))
    return files


def test_every_node_kind_of_the_corpora_has_a_view_whose_properties_read() -> None:
    kinds: set[str] = set()
    parsed = 0
    for path in _corpus_files():
        try:
            tree = parse(preprocess(path.read_text(encoding="utf-8-sig"), path.name).text)
        except InputError:
            continue  # the invalid corpus, and shaders that need a Common tab
        parsed += 1
        for node in _nodes(tree):
            if node.data not in kinds:
                kinds.add(node.data)
            _read_every_property(node)
    assert parsed >= 20
    assert sorted(k for k in kinds if k not in VIEWS) == []


def test_every_rule_of_the_grammar_has_a_view() -> None:
    grammar = (ROOT / "compiler" / "glsl" / "glsl.lark").read_text(encoding="utf-8")
    rules = set(re.findall(r"^([a-z][a-z_]*):", grammar, re.M))  # rules that build a node
    aliases = set(re.findall(r"->\s*([a-z_]+)", grammar))
    built = rules | aliases | {"binary"}  # `binary` comes from parser.py
    assert sorted(k for k in built if k not in VIEWS) == []


def test_cast_gives_the_view_or_none() -> None:
    node = _in_main("x = a + b;", "binary")
    assert isinstance(Binary.cast(node), Binary)
    assert Binary.cast(node).syntax is node  # type: ignore[union-attr]
    assert Call.cast(node) is None
    assert Binary.cast(Token("IDENTIFIER", "x")) is None
    assert Binary.cast(None) is None
    assert isinstance(view(node), Binary)


# --- properties on snippets -------------------------------------------------------------------


def test_function_definition_and_prototype() -> None:
    src = "highp vec3 shade(in vec3 p, out float d[2], inout S s) { return p; }"
    definition = FunctionDefinition(_first(src, "function_definition"))
    assert definition.name == "shade"
    assert isinstance(CompoundStatement.cast(definition.body), CompoundStatement)
    proto = definition.prototype
    assert proto.name == "shade" and isinstance(proto.name_token, Token)
    assert proto.return_type.type.name == "vec3"
    assert proto.return_type.qualifiers == ["highp"]
    params = proto.parameters
    assert [p.name for p in params] == ["p", "d", "s"]
    assert [p.direction for p in params] == ["in", "out", "inout"]
    assert [p.type.name for p in params] == ["vec3", "float", "S"]
    assert [p.array is not None for p in params] == [False, True, False]
    assert proto.parameter_list is not None


def test_prototype_without_parameters_and_void_parameter() -> None:
    assert FunctionPrototype(_first("float f();", "function_prototype")).parameters == []
    (void,) = FunctionPrototype(_first("float f(void);", "function_prototype")).parameters
    assert void.name is None and void.type.name == "void" and void.direction == "in"


def test_variable_declaration_and_declarators() -> None:
    decl = VariableDeclaration(
        _first("const float a = 1.0, b[3], c[2] = x;", "variable_declaration")
    )
    assert decl.type.is_const and decl.type.type.name == "float"
    a, b, c = decl.declarators
    assert (a.name, a.array, _text(a.initializer)) == ("a", None, "1.0")
    assert b.name == "b" and _text(b.array) == "3" and b.initializer is None
    assert c.name == "c" and _text(c.array) == "2" and _text(c.initializer) == "x"
    assert isinstance(a.name_token, Token)


def test_struct_specifier_and_members() -> None:
    src = "struct Ray { vec3 o, d; float t[2]; } r;"
    decl = VariableDeclaration(_first(src, "variable_declaration"))
    struct = decl.type.type.struct
    assert struct is not None and struct.name == "Ray" and decl.type.type.name == "Ray"
    members = struct.members
    assert [m.type.name for m in members] == ["vec3", "float"]
    assert [[d.name for d in m.declarators] for m in members] == [["o", "d"], ["t"]]
    assert members[1].declarators[0].array is not None
    anonymous = StructSpecifier(_first("struct { float x; } s;", "struct_specifier"))
    assert anonymous.name is None


def test_type_specifier_with_array_and_qualifier_layout() -> None:
    spec = Constructor(_in_main("x = float[2](1.0, 2.0);", "constructor")).type
    assert spec.name == "float" and spec.array is not None and spec.struct is None
    src = "layout(location = 0) out vec4 colour;"
    qualifier = VariableDeclaration(_first(src, "variable_declaration")).type.qualifier
    assert qualifier is not None and qualifier.words == ["out"]
    layout = qualifier.layout
    assert layout is not None
    (item,) = layout.items
    assert item.name == "location" and str(item.value) == "0"


def test_other_declarations() -> None:
    precision = PrecisionDeclaration(_first("precision highp float;", "precision_declaration"))
    assert precision.precision == "highp" and precision.type.name == "float"
    block = BlockDeclaration(_first("uniform B { vec3 a; } blocks[2];", "block_declaration"))
    assert block.qualifier.words == ["uniform"] and block.block_name == "B"
    assert block.instance_name == "blocks" and block.array is not None
    assert [m.type.name for m in block.members] == ["vec3"]


def test_statements() -> None:
    stmt = DeclarationStatement(_in_main("float x = 1.0;", "declaration_statement"))
    assert stmt.variables is not None and stmt.variables.declarators[0].name == "x"
    expr = ExpressionStatement(_in_main("x += 1.0;", "expression_statement"))
    assert Assignment.cast(expr.expression) is not None
    branch = IfStatement(_in_main("if (a) x = 1.0; else x = 2.0;", "if_statement"))
    assert _text(branch.condition) == "a"
    assert _text(branch.then_branch) == "x = 1.0"
    assert _text(branch.else_branch) == "x = 2.0"
    assert IfStatement(_in_main("if (a) x = 1.0;", "if_statement")).else_branch is None
    loop = WhileStatement(_in_main("while (i < 3) i++;", "while_statement"))
    assert _text(loop.condition) == "i < 3" and loop.declaration is None
    assert _text(loop.body) == "i ++"
    declared = WhileStatement(_in_main("while (bool go = f()) { }", "while_statement"))
    cond = declared.declaration
    assert isinstance(cond, ConditionDeclaration) and cond.name == "go"
    assert cond.type.type.name == "bool" and _text(cond.initializer) == "f"
    do = DoStatement(_in_main("do i++; while (i < 3);", "do_statement"))
    assert _text(do.body) == "i ++" and _text(do.condition) == "i < 3"
    switch = SwitchStatement(_in_main("switch (k) { case 1: x = 1.0; default: break; }",
                                      "switch_statement"))  # fmt: skip
    assert _text(switch.selector) == "k"
    assert [n.data for n in switch.body] == [  # type: ignore[union-attr]
        "case_label", "expression_statement", "default_label", "jump_statement"
    ]  # fmt: skip
    assert _text(CaseLabel(switch.body[0]).value) == "1"  # type: ignore[arg-type]
    ret = JumpStatement(_in_main("return x * 2.0;", "jump_statement"))
    assert ret.keyword == "return" and _text(ret.value) == "x * 2.0"
    brk = JumpStatement(_in_main("for (;;) break;", "jump_statement"))
    assert brk.keyword == "break" and brk.value is None


def test_expressions() -> None:
    binary = Binary(_in_main("y = a + b * c;", "binary"))
    assert (_text(binary.left), binary.op, _text(binary.right)) == ("a", "+", "b * c")
    assign = Assignment(_in_main("v.x *= 2.0;", "assignment"))
    assert (_text(assign.target), assign.op, _text(assign.value)) == ("v x", "*=", "2.0")
    ternary = Ternary(_in_main("y = c ? a : b;", "ternary"))
    assert [_text(p) for p in (ternary.condition, ternary.if_true, ternary.if_false)] == [
        "c", "a", "b"
    ]  # fmt: skip
    unary = Unary(_in_main("y = -a;", "unary"))
    assert unary.op == "-" and _text(unary.operand) == "a"
    prefix = Prefix(_in_main("++i;", "prefix"))
    assert prefix.op == "++" and _text(prefix.operand) == "i"
    postfix = Postfix(_in_main("i--;", "postfix"))
    assert postfix.op == "--" and _text(postfix.operand) == "i"
    index = Index(_in_main("y = a[i + 1];", "index"))
    assert _text(index.base) == "a" and _text(index.index) == "i + 1"
    field = Field(_in_main("y = s.xyz;", "field"))
    assert _text(field.base) == "s" and field.name == "xyz"
    call = Call(_in_main("y = mix(a, b, 0.5);", "call"))
    assert call.callee_name == "mix" and [_text(a) for a in call.arguments] == ["a", "b", "0.5"]
    assert Call(_in_main("y = f();", "call")).arguments == []
    method = Call(_in_main("n = a.length();", "call"))
    assert method.callee_name is None and Field.cast(method.callee) is not None
    constructor = Constructor(_in_main("y = vec3(1.0);", "constructor"))
    assert constructor.type_name == "vec3" and [_text(a) for a in constructor.arguments] == ["1.0"]
    sequence = Sequence(_in_main("a = 1, b = 2;", "sequence"))
    assert _text(sequence.left) == "a = 1" and _text(sequence.right) == "b = 2"
    assert Variable(_in_main("y = abc;", "variable")).name == "y"
    assert IntLiteral(_in_main("y = 0x10;", "int_literal")).value == 16
    assert IntLiteral(_in_main("y = 7u;", "int_literal")).text == "7u"
    assert FloatLiteral(_in_main("y = 2.5f;", "float_literal")).value == 2.5
    assert BoolLiteral(_in_main("y = false;", "bool_literal")).value is False


def test_accessors_without_a_view() -> None:
    field = _in_main("y = s.xyz;", "field")
    base, name = ast.field_parts(field)
    assert _text(base) == "s" and name == "xyz"
    index = _in_main("y = a[i + 1];", "index")
    assert [_text(p) for p in ast.index_parts(index)] == ["a", "i + 1"]
    ternary = _in_main("y = c ? a : b;", "ternary")
    assert [_text(p) for p in ast.ternary_parts(ternary)] == ["c", "a", "b"]
    branch = _in_main("if (a) x = 1.0; else x = 2.0;", "if_statement")
    assert [_text(p) for p in ast.if_parts(branch)] == ["a", "x = 1.0", "x = 2.0"]
    assert ast.if_parts(_in_main("if (a) x = 1.0;", "if_statement"))[2] is None
    keyword, value = ast.jump_parts(_in_main("return x * 2.0;", "jump_statement"))
    assert keyword == "return" and _text(value) == "x * 2.0"
    assert ast.jump_parts(_in_main("for (;;) break;", "jump_statement")) == ("break", None)
    decl = _first("float a = 1.0, b[3];", "variable_declaration")
    assert [Declarator(d).name for d in ast.declarators(decl)] == ["a", "b"]
    assert ast.declarators(_first("struct S { float x; };", "variable_declaration")) == []
    definition = _first("float f(float x) { return x; }", "function_definition")
    prototype, body = ast.definition_parts(definition)
    assert FunctionPrototype(prototype).name == "f" and body.data == "compound_statement"
    assert ast.leaf_text(_in_main("y = 2.5f;", "float_literal")) == "2.5f"
    assert ast.leaf_text(_in_main("y = abc;", "variable")) == "y"


# --- the for statement: which optional part is there -------------------------------------------

_FORS = {
    "for (int i = 0; i < 3; i++) {}": ("int i 0", "i < 3", "i ++"),
    "for (;; i++) {}": ("", None, "i ++"),
    "for (; c;) {}": ("", "c", None),
    "for (; f(x);) {}": ("", "f x", None),  # a call: a condition, not an update
    "for (;; f(x)) {}": ("", None, "f x"),
    "for (i = 0; ; i += 2) {}": ("i = 0", None, "i += 2"),
    "for (i = 0; i < n; ) {}": ("i = 0", "i < n", None),
    "for (;;) {}": ("", None, None),
}


@pytest.mark.parametrize("source", list(_FORS))
def test_for_statement_parts(source: str) -> None:
    init, cond, update = _FORS[source]
    loop = ForStatement(_in_main(source, "for_statement"))
    assert _text(loop.init) == init
    assert (cond is None) == (loop.condition is None) and (update is None) == (loop.update is None)
    if cond is not None:
        assert _text(loop.condition) == cond
    if update is not None:
        assert _text(loop.update) == update
    assert _text(loop.body) == ""
    assert for_parts(loop.syntax)[1:3] == (loop.condition, loop.update)


@pytest.mark.parametrize("source", list(_FORS))
def test_loop_condition_and_parts_of_a_for(source: str) -> None:
    _, cond, update = _FORS[source]
    node = _in_main(source, "for_statement")
    found = ast.loop_condition(node)
    assert (found is None) == (cond is None) and (cond is None or _text(found) == cond)
    parts = [_text(p) for p in ast.loop_parts(node)]
    assert parts == [p for p in (cond, update) if p is not None] + [""]  # the empty body


def test_loop_condition_and_parts_of_while_and_do() -> None:
    loop = _in_main("while (i < 3) i++;", "while_statement")
    assert _text(ast.loop_condition(loop)) == "i < 3"
    assert [_text(p) for p in ast.loop_parts(loop)] == ["i < 3", "i ++"]
    do = _in_main("do i++; while (i < 3);", "do_statement")
    assert _text(ast.loop_condition(do)) == "i < 3"
    assert [_text(p) for p in ast.loop_parts(do)] == ["i ++", "i < 3"]


def test_lark_and_the_fast_parser_note_the_same_for_parts() -> None:
    from glint.compiler.glsl.parser import glsl_parser

    for source in _FORS:
        text = "void f() {\n" + source + "\n}\n"
        slow = next(n for n in _nodes(glsl_parser().parse(text)) if n.data == "for_statement")
        fast = _in_main(source, "for_statement")
        assert slow == fast
        assert slow.meta.for_parts == fast.meta.for_parts  # type: ignore[attr-defined]


def test_the_evaluator_runs_a_for_loop_without_condition_or_update() -> None:
    src = """
    float count(float n) {
        float k = 0.0;
        for (;; k += 1.0) { if (k >= n) break; }
        float j = 0.0;
        for (; j < n;) { j += 1.0; }
        return k + j;
    }
    """
    out = evaluate(src, "count", [np.array([0.0, 2.0, 3.0])], np.float64)
    assert out.tolist() == [0.0, 4.0, 6.0]


# --- no positional children[i] outside the front end ---------------------------------------


def _indexing_modules() -> set[str]:
    found = set()
    for path in ROOT.rglob("*.py"):
        relative = path.relative_to(ROOT).as_posix()
        if relative.startswith((".", "tests/", "compiler/glsl/")) or "/." in relative:
            continue
        if "children[" in path.read_text(encoding="utf-8"):
            found.add(relative)
    return found


def test_no_module_outside_the_front_end_indexes_children() -> None:
    assert sorted(_indexing_modules()) == [], "read the tree through glsl/ast.py"


def test_ast_is_the_front_end_module() -> None:
    assert ast.__name__ == "glint.compiler.glsl.ast"
    assert Declarator.cast(_in_main("float x;", "declarator")) is not None


# --- accessors for the data-flow analysis --------------------------------------------------------


def test_data_flow_accessors() -> None:
    targets = [_in_main(s, k) for s, k in (("x.y += 1.0;", "assignment"), ("++i;", "prefix"),
                                           ("a[k]--;", "postfix"))]  # fmt: skip
    assert [_text(ast.assigned_target(n)) for n in targets] == ["x y", "i", "a k"]
    assert ast.field_name(_in_main("y = s.xyz;", "field")) == "xyz"
    assert _text(ast.index_expression(_in_main("y = a[i + 1];", "index"))) == "i + 1"
    cond, then, other = ast.if_parts(_in_main("if (a) x = 1.0; else x = 2.0;", "if_statement"))
    assert (_text(cond), _text(then), _text(other)) == ("a", "x = 1.0", "x = 2.0")
    assert ast.if_parts(_in_main("if (a) x = 1.0;", "if_statement"))[2] is None
