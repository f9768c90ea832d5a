"""The expression walker of the first path: the value of each expression, the stores of
assignments, and the events of divisions and builtin calls on the way. A mixin of `Moments`;
`expr` dispatches on the node's kind through `_HANDLERS`."""

from __future__ import annotations

from collections.abc import Callable

from lark import Token, Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    TypeSpecifier,
    binary_parts,
    field_parts,
    first_child,
    index_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ...context import Node
from ..syntax import call_args, callee_name, int_value, is_tree, root_variable
from .builtin_functions import builtin_event, builtin_value
from .operators import FLIP, ORDERED, arith, binary_value
from .state import State, join_states, join_values
from .values import (
    FRAME_ZERO,
    MV,
    Comp,
    Event,
    Sym,
    base_of,
    cast,
    construct,
    f32,
    known,
    size_of,
    truth_of,
    union,
    unknown,
    zero_of,
)


def _map(v: MV, fn: Callable[[Comp], Comp]) -> MV:
    assert v.comps is not None
    base = base_of(v.type)
    comps = tuple(cast(base, fn(c)) if known(c) else Sym() for c in v.comps)
    return MV(v.type, comps, v.tags)


class ExpressionWalker:
    """Evaluates expressions along the first path; `emit` and `_call_user` (CallEvaluator) and
    `_convert` (StatementWalker) come from the other mixins of `Moments`."""

    # (lo, hi) that an expression holds on every run (the semantic model's range): what
    # decides `r2 < rd1` with rd1 = 0 where r2 = dot(z, z) is not known exactly
    bounds: Callable[[Node], tuple[float, float]] | None

    def expr(self, node: Node, state: State) -> MV:
        if isinstance(node, Token):
            return MV(None)
        kind = node.data
        handler = _HANDLERS.get(kind)
        if handler is None:
            return MV(None)
        return handler(self, node, state)

    def _float_literal(self, node: Tree, state: State) -> MV:
        text = leaf_text(node).rstrip("fF")
        try:
            value = f32(float(text))
        except ValueError:
            value = None
        return MV("float", (Sym() if value is None else value,))

    def _int_literal(self, node: Tree, state: State) -> MV:
        text = leaf_text(node)
        value = int_value(text)
        type_ = "uint" if text[-1:] in "uU" else "int"
        return MV(type_, (Sym() if value is None else value,))

    def _bool_literal(self, node: Tree, state: State) -> MV:
        return MV("bool", (leaf_text(node) == "true",))

    def _variable(self, node: Tree, state: State) -> MV:
        name = leaf_text(node)
        value = state.lookup(name)
        if value is not None:
            return value
        if name in FRAME_ZERO:
            type_ = FRAME_ZERO[name]
            return zero_of(type_, frozenset({("frame", name)}))
        if name == "iMouse":
            return zero_of("vec4", frozenset({("mouse",)}))
        if name in ("iResolution", "iChannelTime", "iChannelResolution", "iDate"):
            return unknown({"iResolution": "vec3", "iDate": "vec4"}.get(name, "float[4]"))
        return MV(None)

    def _sequence(self, node: Tree, state: State) -> MV:
        value = MV(None)
        for part in node.children:
            value = self.expr(part, state)
        return value

    def _ternary(self, node: Tree, state: State) -> MV:
        cond_node, if_true, if_false = ternary_parts(node)
        cond = self.expr(cond_node, state)
        truth = truth_of(cond)
        if truth is not None:
            value = self.expr(if_true if truth else if_false, state)
            return value.but(union(value.tags, cond.tags))
        a, b = state.copy(), state.copy()
        va = self.expr(if_true, a)
        vb = self.expr(if_false, b)
        state.become(join_states(state, [a, b]))
        if va.type != vb.type and va.type and vb.type:
            return MV(va.type)
        return join_values([va, vb])

    def _unary(self, node: Tree, state: State) -> MV:
        op = operator(node)
        v = self.expr(operand(node), state)
        if v.comps is None:
            return MV(v.type)
        if op == "-":
            return _map(v, lambda c: -c if not isinstance(c, bool) else Sym())
        if op == "!":
            return _map(v, lambda c: not c if isinstance(c, bool) else Sym())
        if op == "~":
            return _map(
                v, lambda c: ~c if isinstance(c, int) and not isinstance(c, bool) else Sym()
            )
        return v

    def _step(self, node: Tree, state: State) -> MV:
        """`++x` / `x--`: store the stepped value; the expression is the new value (prefix) or
        the old one (postfix)."""
        op, target = operator(node), operand(node)
        old = self.expr(target, state)
        new = arith("+" if op == "++" else "-", old, MV("int", (1,)))
        new = self._convert(old.type, new, state) if old.type else new  # type: ignore[arg-type]
        self._store(target, new, state)
        return new if node.data == "prefix" else old

    def _binary(self, node: Tree, state: State) -> MV:
        left, op, right = binary_parts(node)
        a = self.expr(left, state)
        if op in ("&&", "||"):
            ta = truth_of(a)
            if ta is not None and ta == (op == "||"):  # the right side is not evaluated
                return MV("bool", (ta,), a.tags)
            b = self.expr(right, state)
            tb = truth_of(b)
            if ta is not None:
                return b.but(union(a.tags, b.tags))
            if tb is not None and tb == (op == "||"):
                return MV("bool", (tb,), b.tags)
            return MV("bool", (Sym(),))
        b = self.expr(right, state)
        if op in ("/", "%"):
            self._check_divisor(right, b, a, state)
        value = binary_value(op, a, b)
        if op in ORDERED and self.bounds is not None and truth_of(value) is None:
            value = self._compare_bounds(op, left, a, right, b) or value
        return value

    def _compare_bounds(self, op: str, left: Node, a: MV, right: Node, b: MV) -> MV | None:
        """`x < c` with x unknown but its range on every run on one side of c."""
        if not a.exact() and b.exact() and b.comps and len(b.comps) == 1:
            lo, hi = self.bounds(left)  # type: ignore[misc]
            c = float(b.comps[0])  # type: ignore[arg-type]
        elif not b.exact() and a.exact() and a.comps and len(a.comps) == 1:
            lo, hi = self.bounds(right)  # type: ignore[misc]
            c = float(a.comps[0])  # type: ignore[arg-type]
            op = FLIP[op]
        else:
            return None
        result = None
        if op == "<":
            result = False if lo >= c else (True if hi < c else None)
        elif op == "<=":
            result = False if lo > c else (True if hi <= c else None)
        elif op == ">":
            result = False if hi <= c else (True if lo > c else None)
        elif op == ">=":
            result = False if hi < c else (True if lo >= c else None)
        return None if result is None else MV("bool", (result,), union(a.tags, b.tags))

    def _check_divisor(self, divisor: Node, value: MV, numerator: MV, state: State) -> None:
        if value.has_zero() and base_of(value.type) != "bool":
            self.emit(Event("divide", divisor, value, numerator, union(value.tags, state.control)))

    def _assignment(self, node: Tree, state: State) -> MV:
        target, op, rhs = binary_parts(node)
        value = self.expr(rhs, state)
        if op != "=":
            old = self.expr(target, state)
            if op == "/=":
                self._check_divisor(rhs, value, old, state)
            value = binary_value(op[:-1], old, value)
        target_type = self.expr(target, state).type
        if target_type and size_of(target_type) is not None and value.comps is not None:
            value = self._convert(target_type, value, state)
        elif state.control:
            value = value.but(union(value.tags, state.control))
        self._store(target, value, state)
        return value

    def _store(self, target: Node, value: MV, state: State) -> None:
        name = root_variable(target)
        if name is None:
            return
        old = state.lookup(name)
        if old is None:
            return
        if is_tree(target, "variable"):
            if old.type and value.type != old.type:
                value = MV(old.type, value.comps if size_of(old.type) and value.comps and
                           len(value.comps) == size_of(old.type) else None, value.tags)  # fmt: skip
                if value.comps is None and size_of(old.type):
                    value = unknown(old.type)
            state.assign(name, value)
            return
        base = first_child(target)  # type: ignore[arg-type]  # of a field or an index
        if is_tree(base, "variable") and old.comps is not None:
            slots: list[int] | None = None
            if is_tree(target, "field"):
                letters = field_parts(target)[1]  # type: ignore[arg-type]
                slots = list(T.swizzle_indices(letters) or [-1])
            elif is_tree(target, "index"):
                i = self.expr(index_parts(target)[1], state)  # type: ignore[arg-type]
                if i.comps and known(i.comps[0]) and isinstance(i.comps[0], int):
                    slots = [int(i.comps[0])]
            if slots and all(0 <= s < len(old.comps) for s in slots):
                comps = list(old.comps)
                new = value.comps if value.comps is not None else None
                for k, s in enumerate(slots):
                    if new is not None and len(new) == len(slots):
                        comps[s] = cast(base_of(old.type), new[k])
                    elif new is not None and len(new) == 1:
                        comps[s] = cast(base_of(old.type), new[0])
                    else:
                        comps[s] = Sym()
                state.assign(name, MV(old.type, tuple(comps), union(old.tags, value.tags)))
                return
        state.assign(name, unknown(old.type))

    def _forget(self, target: Node, state: State) -> None:
        name = root_variable(target)
        if name is not None and (old := state.lookup(name)) is not None:
            state.assign(name, unknown(old.type))

    def _field(self, node: Tree, state: State) -> MV:
        base, letters = field_parts(node)
        v = self.expr(base, state)
        if v.comps is None or size_of(v.type) is None:
            return MV(None)
        slots = list(T.swizzle_indices(letters) or [-1])  # -1: no swizzle
        if not all(0 <= s < len(v.comps) for s in slots) or len(slots) > 4:
            return MV(None)
        comps = tuple(v.comps[s] for s in slots)
        return MV(T.swizzle(v.type, letters), comps, v.tags)

    def _index(self, node: Tree, state: State) -> MV:
        base, index = index_parts(node)
        v = self.expr(base, state)
        i = self.expr(index, state)
        if v.comps is not None and size_of(v.type) and i.comps and known(i.comps[0]):
            k = i.comps[0]
            if isinstance(k, int) and 0 <= k < len(v.comps):
                return MV(T.element(v.type), (v.comps[k],), union(v.tags, i.tags))
        return unknown(T.element(v.type)) if T.element(v.type) else MV(None)

    def _constructor(self, node: Tree, state: State) -> MV:
        spec = TypeSpecifier(first_child(node))  # type: ignore[arg-type]
        type_ = str(spec.head)
        is_array = spec.array is not None
        args = [self.expr(a, state) for a in call_args(node)]
        n = size_of(type_)
        if is_array or n is None:
            return MV(type_ + ("[]" if is_array else ""))
        return construct(type_, n, args)

    def _call(self, node: Tree, state: State) -> MV:
        name = callee_name(node)
        arg_nodes = call_args(node)
        if name is None:  # a method: v.length()
            head = first_child(node)  # the callee
            if is_tree(head, "field"):
                base, method = field_parts(head)  # type: ignore[arg-type]
                if method == "length":
                    self.expr(base, state)
            return unknown("int")
        args = [self.expr(a, state) for a in arg_nodes]
        if name in self.functions:
            return self._call_user(node, name, args, state)
        if name in BUILTIN_FUNCTIONS:
            event = builtin_event(node, name, arg_nodes, args, state.control)
            if event is not None:
                self.emit(event)
            return builtin_value(name, args)
        if size_of(name) is not None:  # a constructor the parser saw as a call
            return construct(name, size_of(name), args)  # type: ignore[arg-type]
        return MV(name if name[:1].isupper() else None)


_HANDLERS: dict[str, Callable[[ExpressionWalker, Tree, State], MV]] = {
    "float_literal": ExpressionWalker._float_literal,
    "int_literal": ExpressionWalker._int_literal,
    "bool_literal": ExpressionWalker._bool_literal,
    "variable": ExpressionWalker._variable,
    "sequence": ExpressionWalker._sequence,
    "ternary": ExpressionWalker._ternary,
    "unary": ExpressionWalker._unary,
    "prefix": ExpressionWalker._step,
    "postfix": ExpressionWalker._step,
    "binary": ExpressionWalker._binary,
    "assignment": ExpressionWalker._assignment,
    "field": ExpressionWalker._field,
    "index": ExpressionWalker._index,
    "constructor": ExpressionWalker._constructor,
    "call": ExpressionWalker._call,
}
