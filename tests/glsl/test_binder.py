"""The binder (compiler/glsl/binder.py): scopes, what each name means, reads and writes, the
call graph and the per-function summaries."""

from __future__ import annotations

from pathlib import Path

import pytest
from lark import Tree

from glint.compiler.glsl.binder import Bindings, Function, Symbol, Use, bind
from glint.compiler.glsl.parser import parse_source
from glint.compiler.target.shadertoy import shadertoy_types

CORPUS = Path(__file__).resolve().parents[2].parent / "shared" / "corpus"


def _bind(text: str) -> Bindings:
    tree, _ = parse_source(text, "test.glsl")
    return bind(tree, shadertoy_types())


def _uses(b: Bindings, name: str) -> list[Use]:
    return [u for u in b.uses if u.name == name]


def _fn(b: Bindings, name: str, arity: int | None = None) -> Function:
    found = [f for f in b.functions if f.name == name and (arity is None or f.arity == arity)]
    assert len(found) == 1, found
    return found[0]


def _line(symbol: Symbol | None) -> int:
    assert symbol is not None and symbol.token is not None
    return symbol.token.line  # type: ignore[return-value]


# --- scopes and shadowing ------------------------------------------------------------------

SHADOWING = """
float x = 1.0;
float f(float a) {
    float r = x;
    vec2 x = vec2(x);
    for (int x = 0; x < 2; x++) { r += float(x); }
    { bool x = true; r += x ? 1.0 : 0.0; }
    return r + x.y;
}
"""


def test_a_local_shadows_a_global_from_its_declaration_on() -> None:
    b = _bind(SHADOWING)
    xs = _uses(b, "x")
    kinds = [(u.node.meta.line, u.symbol.kind, u.symbol.type) for u in xs]  # type: ignore[union-attr]
    assert kinds == [
        (4, "global", "float"),  # r = x
        (5, "global", "float"),  # vec2 x = vec2(x): the initializer reads the outer x
        (6, "local", "int"),  # the for's x, in its condition, update and body
        (6, "local", "int"),
        (6, "local", "int"),
        (7, "local", "bool"),  # the block's x
        (8, "local", "vec2"),  # after the for and the block, the vec2 again
    ]


def test_scopes_nest_with_the_nodes_that_open_them() -> None:
    b = _bind(SHADOWING)
    fn = _fn(b, "f")
    assert fn.scope is not None and fn.scope.parent is b.file and b.file.parent is b.builtins
    assert fn.scope.node is fn.definition
    inner = {s.kind: s for s in fn.scope.children}
    assert set(inner) == {"loop", "block"}
    assert [s.name for s in inner["loop"]] == ["x"] and inner["loop"].node.data == "for_statement"  # type: ignore[union-attr]
    assert b.scope_of(inner["block"].node) is inner["block"]  # type: ignore[arg-type]
    assert [p.name for p in fn.parameters] == ["a"] and fn.parameters[0].scope is fn.scope
    assert [s.name for s in fn.locals] == ["r", "x", "x", "x"]
    assert fn.scope.lookup("a") is fn.parameters[0]
    assert b.file.lookup("iTime") is not None and b.file.lookup("iTime").kind == "builtin"  # type: ignore[union-attr]


def test_symbols_carry_type_qualifiers_and_declaring_node() -> None:
    b = _bind(
        "struct S { vec3 p; float w[2]; };\n"
        "const float K = 2.0;\n"
        "uniform vec3 u;\n"
        "float g(const in float a, inout S s, out vec2 o[3]) { o[0] = vec2(a); return K; }\n"
    )
    by_name = {s.name: s for s in b.symbols}
    assert by_name["K"].kind == "global" and by_name["K"].is_const and by_name["K"].type == "float"
    assert by_name["u"].qualifiers == ("uniform",)
    assert by_name["S"].kind == "struct" and by_name["S"].node.data == "struct_specifier"  # type: ignore[union-attr]
    assert (by_name["w"].kind, by_name["w"].type) == ("field", "float[2]")
    a, s, o = _fn(b, "g").parameters
    assert (a.direction, s.direction, o.direction) == ("in", "inout", "out")
    assert (s.type, o.type) == ("S", "vec2[3]") and a.is_const
    assert _fn(b, "g").symbol.type == "float" and _line(a) == 4


def test_a_while_declaration_lives_in_the_loop() -> None:
    b = _bind("void f(int n) { while (bool go = n > 0) { n--; go; } }")
    go = [u for u in _uses(b, "go")]
    assert go[0].symbol is not None and go[0].symbol.scope.kind == "loop"


# --- reads and writes ----------------------------------------------------------------------

READS_WRITES = """
void set(out float o, inout float io, float i) { o = i; io += i; }
void f() {
    float a, b, c, d = 1.0;
    vec3 v;
    set(a, b, c);
    v.xy = vec2(d);
    d *= 2.0;
    d++;
    --c;
    v[int(d)] = 0.0;
}
"""


def _flags(b: Bindings, name: str) -> list[tuple[bool, bool]]:
    return [(u.read, u.write) for u in _uses(b, name) if u.function and u.function.name == "f"]


def test_reads_and_writes_are_told_apart() -> None:
    b = _bind(READS_WRITES)
    assert _flags(b, "a") == [(False, True)]  # an out argument: written, not read
    assert _flags(b, "b") == [(True, True)]  # inout: both
    assert _flags(b, "c") == [(True, False), (True, True)]  # an in argument; --c
    assert _flags(b, "v") == [(False, True), (False, True)]  # a swizzle write, an index write
    # d: read in vec2(d), compound assignment, ++, read in the index
    assert _flags(b, "d") == [(True, False), (True, True), (True, True), (True, False)]
    assert _fn(b, "f").written_names == {"a", "b", "c", "d", "v"}
    d = next(s for s in b.symbols if s.name == "d")
    assert len(d.writes) == 2 and len(d.reads) == 4


def test_modf_writes_its_second_argument() -> None:
    b = _bind("float f(float x) { float i; return modf(x, i) + i; }")
    assert [(u.read, u.write) for u in _uses(b, "i")] == [(False, True), (True, False)]


def test_names_the_file_does_not_declare_resolve_to_nothing() -> None:
    b = _bind("float f() { return undeclared + iTime; }")
    assert b.symbol_of(_uses(b, "undeclared")[0].node) is None
    assert b.symbol_of(_uses(b, "iTime")[0].node).kind == "builtin"  # type: ignore[union-attr]


# --- the call graph ------------------------------------------------------------------------

CALLS = """
float later(vec2 p);
float h(float x) { return x; }
float h(vec2 x) { return x.x; }
float h(float x, float y) { return x + y; }
float rec(float x) { return x > 0.0 ? rec(x - 1.0) : 0.0; }
void unused() { h(1.0); }
void mainImage(out vec4 c, in vec2 p) {
    c = vec4(later(p) + h(p) + h(1.0, 2.0) + h(p.x) + rec(1.0));
}
float later(vec2 p) { return length(p); }
"""


def test_a_prototype_merges_with_its_definition() -> None:
    b = _bind(CALLS)
    later = _fn(b, "later")
    assert later.definition is not None and len(later.prototypes) == 2
    call = next(c for c in b.calls if c.name == "later")
    assert call.callee is later and call.caller is _fn(b, "mainImage")
    assert [p.name for p in later.parameters] == ["p"]


def test_overloads_are_told_apart_by_arity_and_type() -> None:
    b = _bind(CALLS)
    main = _fn(b, "mainImage")
    callees = {(f.name, f.parameter_types) for f in main.callees}
    assert callees == {
        ("later", ("vec2",)),
        ("h", ("vec2",)),
        ("h", ("float", "float")),
        ("h", ("float",)),
        ("rec", ("float",)),
    }
    builtin = next(c for c in b.calls if c.name == "length")
    assert builtin.callee is None and builtin.targets == []


def test_reachable_from_the_entry_point_and_recursion() -> None:
    b = _bind(CALLS)
    assert b.entry is _fn(b, "mainImage")
    reached = {f.name for f in b.reachable()}
    assert reached == {"mainImage", "later", "h", "rec"}
    assert _fn(b, "unused") not in b.reachable()
    assert {f.name for f in _fn(b, "h", 2).callers} == {"mainImage"}
    assert b.recursive == {_fn(b, "rec")}


# --- summaries -------------------------------------------------------------------------------

SUMMARIES = """
void all_paths(out float a, out vec3 v, bool k) {
    if (k) { a = 1.0; v.xy = vec2(0.0); v.z = 1.0; return; }
    a = 2.0;
    v = vec3(0.0);
}
void one_branch(out float a, bool k) { if (k) a = 1.0; }
void in_loop(out float a, int n) { for (int i = 0; i < n; i++) a = 1.0; }
void forever(out float a) { for (;;) { a = 1.0; break; } }
void early(out float a, bool k) { if (k) return; a = 1.0; }
void partial(out vec3 v) { v.xy = vec2(1.0); }
void through_call(out float a) { all_paths(a, v3(), true); }
vec3 v3() { return vec3(0.0); }
float ends(bool k) { if (k) return 1.0; }
float returns(bool k) { if (k) return 1.0; else return 0.0; }
float loops(float x) { for (;;) { if (x > 1.0) return x; x *= 2.0; } }
float loop_may_end(float x) { for (int i = 0; i < 4; i++) { if (x > 1.0) return x; } }
float switches(int i) { switch (i) { case 0: return 1.0; default: return 2.0; } }
"""


def _written(b: Bindings, name: str) -> set[str]:
    summary = _fn(b, name).summary
    assert summary is not None
    return {p.name for p in summary.written_on_every_path}


def test_out_parameters_written_on_every_path() -> None:
    b = _bind(SUMMARIES)
    assert _written(b, "all_paths") == {"a", "v"}  # v in full through swizzles on one path
    assert _written(b, "one_branch") == set()
    assert _written(b, "in_loop") == set()  # the loop may not run
    assert _written(b, "forever") == {"a"}  # left by its break only
    assert _written(b, "early") == set()
    assert _written(b, "partial") == set()
    assert _written(b, "through_call") == {"a"}  # an out argument is a write


def test_the_end_reachable_without_return() -> None:
    b = _bind(SUMMARIES)

    def reachable(name: str) -> bool:
        summary = _fn(b, name).summary
        assert summary is not None
        return summary.end_reachable

    assert reachable("ends") and reachable("loop_may_end")
    assert not reachable("returns") and not reachable("loops") and not reachable("switches")
    assert len(_fn(b, "returns").summary.returns) == 2  # type: ignore[union-attr]


# --- the corpus ------------------------------------------------------------------------------


@pytest.mark.skipif(not (CORPUS / "shadertoy").is_dir(), reason="no corpus beside")
def test_every_name_resolves_on_valid_corpus_shaders() -> None:
    valid = (CORPUS / "glslang-valid.txt").read_text().split()
    seen = 0
    for name in valid:
        path = CORPUS / "shadertoy" / name
        if not path.is_file():
            continue
        tree, _ = parse_source(path.read_text(encoding="utf-8", errors="replace"), name)
        assert isinstance(tree, Tree)
        b = bind(tree, shadertoy_types())
        missing = sorted({u.name for u in b.uses if u.symbol is None})
        assert not missing, f"{name}: {missing}"
        called = [c for c in b.calls if c.callee is None and c.targets]
        assert not called, f"{name}: overloads not told apart {[c.name for c in called]}"
        seen += 1
    assert seen > 100
