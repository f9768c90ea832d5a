"""Definite assignment: at each read of a local variable or an `out` parameter, is it certainly
written on every path that reaches the read? And at each exit of a function, which `out`
parameters are written?

A small forward analysis over the statement tree of each function (no control-flow graph):
if/else join, loops may run zero times (unless their bounds say otherwise), `switch` falls
through, `return`/`break`/`continue`/`discard` end a path. A condition leaves two states, where
it is true and where it is false: inside `if (a && f(x))` the call ran; and a condition that the
semantic model's value ranges decide (`abs(uv.x) < 1.0` with uv in [0, 1]) has one side only. A
loop that surely runs is analysed in two passes, its first iteration and the later ones; in the
first, and at a loop's first test, the values its locals were given before it
(known_values.py) decide conditions too (`if (h < EPS) break;` with h = 1.0 does not break).
Counted loops with constant bounds that neither break nor continue are searched: a branch
`if (d < md)` directly in their bodies, where `md` changes only in the branch, is taken on some
iteration when the values known there make the condition true for some values of the counters
(`md = 8.0` and d below 2 in the middle cell): what it writes is written when the loops end.
A flag tested bare (`if (isGrnd)`) carries a promise for each variable its branches assign: the
components written or, where the flag was set to `true`, all of them; where the test finds the
flag false, the promise is what is written (`isGrnd = true;` on the path that leaves `col` to
`if (isGrnd) col = ...;`).
A state maps each tracked variable to a bit mask of its written components (vectors are tracked
per component, through swizzles; everything else as a whole). Joins intersect the masks. Since
masks only grow, a loop body is analysed once, with the state on entry, and no fixed point is
needed.

The analysis prefers silence to guessing: a write through a path it cannot follow
(`a[i].x = ...`, a struct member) counts as a write of the whole variable, and a variable passed
to a function this file does not define counts as written, never as read.

Each function leaves a summary for the calls after it: which components of each `inout`
parameter it may read before writing them. An `inout` argument the callee only writes is an
`out` (`march(ro, rd, t)` that starts with `t = 0.`), and one whose callee reads only `.zw`
first is read for `.zw` only at the call.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from itertools import compress
from operator import ne
from typing import Literal

from lark import Token, Tree

from glint.compiler.glsl.ast import (
    Call,
    DeclarationStatement,
    DoStatement,
    FunctionDefinition,
    JumpStatement,
    Sequence,
    SwitchStatement,
    Ternary,
    VariableDeclaration,
    WhileStatement,
    assigned_target,
    binary_parts,
    call_arguments,
    field_name,
    first_child,
    for_parts,
    if_parts,
    index_expression,
    int_value,
    operand,
    operator,
    token_text,
    variable_name,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ..context import LintContext, Node, walk_kind
from .declarations import struct_members
from .known_values import Comps, KnownValues
from .model import Model, condition_truth, semantic_model
from .syntax import (
    names_in,
    parameter_parts,
    prototype_parts,
    same_expression,
    type_of_declaration,
)

State = dict[int, int]  # id of a Var -> mask of written components
SWIZZLE_SETS = ("xyzw", "rgba", "stpq")
_SHORT_CIRCUIT = ("&&", "||", "^^")
# Builtins with `out` parameters in GLSL ES 3.00, by position.
_BUILTIN_QUALIFIERS: dict[str, tuple[str, ...]] = {"modf": ("in", "out")}
_MAX_FIELDS = 30  # struct members tracked one by one; a larger struct is tracked as a whole
# A chain of at least this many comparisons of one value (`t < t1 ... else if (t < t2) ...`),
# or two `==` tests of ids, is a case analysis its author meant to be exhaustive.
_CASES = 3
_COMPARISONS = ("<", "<=", ">", ">=", "==")


@dataclass(eq=False)
class Var:
    """A tracked variable: a local declared without a value, or an `out` parameter."""

    name: str
    token: Token  # its name where declared
    width: int  # components tracked: 2-4 for vectors, a struct's members, else 1
    # inout, and in for a struct: tracked only for the function's summary
    kind: Literal["local", "out", "inout", "in"]
    fields: tuple[str, ...] = ()  # a struct's members, one component each
    depth: int = 0  # how many guards are open where it is declared
    struct: str = ""  # the struct type's name, for a struct

    @property
    def full(self) -> int:
        return (1 << self.width) - 1


# An open condition around a statement: (id of the condition, the names it reads, the branch,
# the values it tests: `hit`, `idObj` of `idObj == 1`, `fragCoord.x` of `fragCoord.x > 1.`)
Guard = tuple[int, frozenset[str], Node, frozenset[str]]


@dataclass
class Read:
    """A read of components that are not written on some path to it."""

    var: Var
    node: Node
    missing: int  # mask of the components that may be unwritten
    guards: tuple[Guard, ...] = ()  # the conditions it sits under, inside the variable's scope
    # a read through a call (`shade(s)` where shade reads `s.m`): component -> the callee's read
    origins: dict[int, Node] = field(default_factory=dict)
    # the conditions it sits under are tied to those of some write (`if (hit) n = ...;` then
    # `if (hit) use(n)`, `if (t < tmin) { tmin = t; n = ...; }` then `if (tmin < 1e9) use(n)`):
    # the path that skips the write is one the author ruled out
    correlated: bool = False


@dataclass
class Exit:
    """A way out of the function: a `return`, or the end of the body (node None)."""

    node: Node | None
    state: State


@dataclass
class FunctionFlow:
    name: str
    definition: Tree
    outs: list[Var]  # the tracked `out` parameters, in order
    returns: str = "void"  # the return type
    reads: list[Read] = field(default_factory=list)
    exits: list[Exit] = field(default_factory=list)
    # per parameter position: for an `inout` one (or an `in` struct), the mask of its
    # components the function may read before writing them (0: it only writes it); None for
    # the other parameters
    inout_reads: list[int | None] = field(default_factory=list)
    # per parameter position, as inout_reads: component -> the read that reads it first
    origins: list[dict[int, Node] | None] = field(default_factory=list)


Summaries = dict[tuple[str, int], "FunctionFlow | None"]  # None: overloads, no summary


def function_flows(ctx: LintContext) -> list[FunctionFlow]:
    """The definite-assignment results of every function definition (once per file)."""
    return ctx.memo(_function_flows)


def _function_flows(ctx: LintContext) -> list[FunctionFlow]:
    flows: list[FunctionFlow] = []
    if ctx.tree is None or ctx.pre is None:
        return flows
    signatures = _signatures(ctx.tree)
    consts = _const_ints(ctx.tree)
    model = _Facts(ctx)
    summaries: Summaries = {}
    structs = {
        name: tuple(members)
        for name, members in struct_members(walk_kind(ctx.tree, "struct_specifier")).items()
        if len(members) <= _MAX_FIELDS
    }
    for node in ctx.tree.children:
        if isinstance(node, Tree) and node.data == "function_definition":
            analyzer = _Analyzer(signatures, consts, ctx.pre.text, model, summaries)
            analyzer.structs = structs
            flow = analyzer.function(node)
            flows.append(flow)
            # functions are defined before the calls that use the summary (no
            # recursion in GLSL); overloads of one arity share no summary
            key = (flow.name, len(flow.inout_reads))
            summaries[key] = None if key in summaries else flow
    return flows


def mask_names(var: Var, mask: int) -> str:
    """`.xyz`-style names of the components in `mask` ("" for the whole variable); a struct's
    members by name (`.m`, `.{m, d}`)."""
    if var.width == 1 or mask == var.full:
        return ""
    if var.fields:
        picked = [name for i, name in enumerate(var.fields) if mask >> i & 1]
        return "." + picked[0] if len(picked) == 1 else ".{" + ", ".join(picked) + "}"
    return "." + "".join("xyzw"[i] for i in range(var.width) if mask >> i & 1)


# --- the tree ------------------------------------------------------------------------------


def vector_width(type_name: str) -> int:
    """Components of a vector type (vec3 -> 3), 1 for anything else."""
    for prefix in ("vec", "ivec", "uvec", "bvec"):
        if type_name.startswith(prefix) and type_name[len(prefix) :] in ("2", "3", "4"):
            return int(type_name[-1])
    return 1


def swizzle(name: str, width: int) -> tuple[int, ...] | None:
    """Component indices of a swizzle such as `xy` or `bgr`, or None if it is not one."""
    if not 1 <= len(name) <= 4:
        return None
    for letters in SWIZZLE_SETS:
        if all(c in letters for c in name):
            indices = tuple(letters.index(c) for c in name)
            return indices if all(i < width for i in indices) else None
    return None


def _signatures(tree: Tree) -> dict[str, list[tuple[str, ...]]]:
    """Parameter qualifiers of every user function, per overload."""
    found: dict[str, list[tuple[str, ...]]] = {}
    for node in tree.children:
        if not isinstance(node, Tree):
            continue
        definition = FunctionDefinition.cast(node)
        proto = definition.prototype.syntax if definition is not None else node
        if isinstance(proto, Tree) and proto.data == "function_prototype":
            _, name, params = prototype_parts(proto)
            qualifiers = tuple(parameter_parts(p)[0] for p in params)
            if qualifiers == ("in",) and parameter_parts(params[0])[1] == "void":
                qualifiers = ()  # `f(void)`
            found.setdefault(str(name), []).append(qualifiers)
    return found


def _const_ints(tree: Tree) -> dict[str, int]:
    """Global `const int N = <literal>;` values, to see that `for (i = 0; i < N; ...)` runs."""
    found: dict[str, int] = {}
    for node in tree.children:
        decl = VariableDeclaration.cast(node)
        if decl is None or not decl.type.is_const:
            continue
        for declarator in decl.declarators:
            init = declarator.initializer
            if declarator.array is None and init is not None:
                value = _int_value(init)
                if value is not None:
                    found[declarator.name] = value
    return found


def _int_value(node: Node) -> int | None:
    if isinstance(node, Tree) and node.data == "int_literal":
        return int_value(token_text(node))  # type: ignore[arg-type]
    if isinstance(node, Tree) and node.data == "unary" and operator(node) == "-":
        inner = _int_value(operand(node))
        return None if inner is None else -inner
    return None


def _join(states: Iterable[State | None]) -> State | None:
    """The state where paths meet: a component is written if it is on every path."""
    result: State | None = None
    for state in states:
        if state is None:
            continue
        if result is None:
            result = dict(state)
            continue
        keys = list(result)
        if keys == list(state):
            # Copies of one state that differ in a few masks: find those with C-level
            # iteration; a Python-level pass over every tracked variable at each merge was
            # quadratic in long functions.
            for key in list(compress(keys, map(ne, result.values(), state.values()))):
                result[key] &= state[key]
        else:
            result = {k: v & state[k] for k, v in result.items() if k in state}
    return result


class _Facts:
    """What the semantic model knows of conditions and loop bounds, built on first use (a file
    without a condition does not need it). Where the model cannot evaluate (an expression too
    deep for its recursion), it knows nothing."""

    def __init__(self, ctx: LintContext) -> None:
        self.ctx = ctx
        self.model: Model | None = None
        self.failed = False

    def get(self) -> Model | None:
        if self.model is None and not self.failed:
            try:
                self.model = semantic_model(self.ctx)
            except (RecursionError, ValueError):
                self.failed = True
        return self.model

    def truth(self, cond: Node) -> bool | None:
        model = self.get()
        try:
            return condition_truth(model, cond) if model is not None else None
        except RecursionError:
            return None

    def range(self, node: Node) -> tuple[float, float] | None:
        model = self.get()
        try:
            got = model.range_of(node) if model is not None else None
        except RecursionError:
            return None
        return None if got is None or got.is_unknown or got.lo > got.hi else (got.lo, got.hi)

    def comps(self, node: Node) -> Comps | None:
        """Ranges per component of an expression (on every run), for KnownValues."""
        model = self.get()
        try:
            got = model.value_of(node) if model is not None else None
        except RecursionError:
            return None
        if got is None:
            return None
        if got.comps:
            return tuple(got.comps)
        width = vector_width(got.type or "")
        return (got.range,) * width if got.type else None


@dataclass
class _Target:
    """An enclosing loop or switch: the states that `break` and `continue` leave with."""

    loop: bool
    breaks: list[State] = field(default_factory=list)
    continues: list[State] = field(default_factory=list)


@dataclass(eq=False)
class _Sweep:
    """A counted loop analysed in two passes, for the branch a search surely takes on some
    iteration (`if (d < md) { md = d; mr = r; }` with md = 8.0 and d below 2 in the middle
    cell): the loop, its counter and the values it takes (None: unknown or too many)."""

    loop: Tree
    counter: str
    values: tuple[float, ...] | None
    depth: int  # guards open at the loop: an `if` directly in its body has as many
    targets: int  # loops and switches open in its body: an `if` directly in it has as many
    clock: int  # the known values' clock before the loop: older values are its first iteration's
    first: bool = True  # in the first pass
    # id of an `if` surely taken on some iteration -> the states its taken branch ends with
    taken: dict[int, list[State]] = field(default_factory=dict)


class _Analyzer:
    def __init__(
        self,
        signatures: dict[str, list[tuple[str, ...]]],
        consts: dict[str, int],
        text: str,
        model: _Facts | None = None,
        summaries: Summaries | None = None,
    ) -> None:
        self.signatures = signatures
        self.consts = consts
        self.text = text
        self.model = model
        self.summaries = summaries if summaries is not None else {}
        self.structs: dict[str, tuple[str, ...]] = {}  # struct name -> its members
        # id of a tracked inout (or in struct) parameter -> its position
        self.inout_position: dict[int, int] = {}
        self.guards: list[Guard] = []  # the conditions around the statement analysed
        # id of a tracked variable -> (the guards, the innermost branch) of each write of it
        self.writes: dict[int, list[tuple[tuple[Guard, ...], Node | None]]] = {}
        self.assigned_cache: dict[int, frozenset[str]] = {}  # id of a branch -> names it assigns
        self.chains: dict[int, bool] = {}  # id of an else-if link -> whether its chain is a case
        # counters of loops analysed in two passes: (name, start range, first iteration?)
        self.counters: list[tuple[str, tuple[float, float] | None, bool]] = []
        self.scopes: list[dict[str, Var | None]] = []  # None: a name that is not tracked
        self.targets: list[_Target] = []
        self.flow: FunctionFlow | None = None
        self.reported: set[int] = set()  # ids of nodes already reported
        # the values of locals where the analysis stands (known_values.py)
        self.known = KnownValues(self.comps, self.structs)
        self.peels = 0  # loops being analysed in two passes around the statement
        # inside the first pass of a peeled loop, or at a loop's first test: where the values
        # set before a loop decide what the model's ranges (widened over the loop) cannot
        self.asking = 0
        self.loop_names: dict[int, frozenset[str]] = {}  # id of a loop -> names it may write
        self.sweeps: list[_Sweep] = []  # the loops analysed in two passes around the statement
        self.taken: dict[int, _Sweep] = {}  # id of an `if` surely taken -> the loop it is in
        # id of a loop -> its writes: name -> where each write starts (positions in the text)
        self.loop_writes: dict[int, dict[str, list[int]]] = {}
        # flags: name of a local tested bare (`if (isGrnd)`) -> the names its branches assign
        self.flag_names: dict[str, frozenset[str]] = {}
        # name of a flag -> (a variable, its promise): a pseudo variable whose components are
        # those of the variable that are written, or all of them where the flag is true (set
        # with `flag = true` on a path that leaves the value to `if (flag) v = ...;`)
        self.promises: dict[str, list[tuple[Var, Var]]] = {}
        self.promised: dict[int, list[Var]] = {}  # id of a variable -> its promises

    def comps(self, node: Node) -> Comps | None:
        return self.model.comps(node) if self.model is not None else None

    # --- functions and statements -----------------------------------------------------------

    def function(self, node: Tree) -> FunctionFlow:
        definition = FunctionDefinition(node)
        body = definition.body
        returns, name, params = prototype_parts(definition.prototype.syntax)
        flow = FunctionFlow(str(name), node, [], returns)
        self.flow = flow
        self.scopes = [{}]
        self.known.clear()
        self.known.structs = self.structs
        self.flag_names = self.flags(body)
        self.promises, self.promised = {}, {}
        state: State = {}
        parts = [parameter_parts(param) for param in params]
        if len(parts) == 1 and parts[0][:2] == ("in", "void") and parts[0][3] is None:
            parts = []  # `f(void)`
        flow.inout_reads = [None] * len(parts)
        flow.origins = [None] * len(parts)
        for position, (qualifier, type_name, is_array, pname) in enumerate(parts):
            width, fields = self.shape(type_name, is_array)
            # an `in` struct: which of its members the function reads, for its callers
            summarised = qualifier == "inout" or (qualifier == "in" and bool(fields))
            if summarised:
                flow.inout_reads[position] = 0
                flow.origins[position] = {}
            if pname is None:
                continue
            if qualifier == "out" or summarised:
                var = Var(str(pname), pname, width, qualifier, fields)  # type: ignore[arg-type]
                var.struct = type_name if fields else ""
                if qualifier == "out":
                    flow.outs.append(var)
                else:
                    self.inout_position[id(var)] = position
                self.scopes[-1][var.name] = var
                state[id(var)] = 0
            else:
                self.scopes[-1][str(pname)] = None
        end = self.block(body.children, state)  # the compound statement's statements
        if end is not None:
            flow.exits.append(Exit(None, end))
        for read in flow.reads:
            read.correlated = self.correlated(read)
        return flow

    def shape(self, type_name: str, is_array: bool) -> tuple[int, tuple[str, ...]]:
        """(components tracked, struct members) of a variable of this type."""
        if is_array:
            return 1, ()
        fields = self.structs.get(type_name, ())
        return (len(fields), fields) if fields else (vector_width(type_name), ())

    def correlated(self, read: Read) -> bool:
        """Whether some write of the variable is tied to the conditions the read sits under:
        each condition that guards the write but not the read reads a name the read's own
        conditions read, or the write's branch also sets a name those conditions test (a flag,
        the running minimum that a sentinel test checks)."""
        own = {guard[0] for guard in read.guards}
        tested = frozenset().union(*(g[1] for g in read.guards))
        values = frozenset().union(*(g[3] for g in read.guards))
        if not tested:
            return False
        for guards, branch in self.writes.get(id(read.var), []):
            extra = [g for g in guards if g[0] not in own]
            if not extra:
                continue  # the write is under the read's conditions: it does not cover it
            if branch is not None and self.assigned(branch) & tested:
                return True
            if all(g[3] & values for g in extra):
                return True
        return False

    def assigned(self, branch: Node) -> frozenset[str]:
        """The names a branch may assign (computed once per branch)."""
        key = id(branch)
        if key not in self.assigned_cache:
            names: set[str] = set()
            for sub in walk_kind(branch, "assignment", "prefix", "postfix"):
                root = _root(assigned_target(sub))
                if root is not None:
                    names.add(variable_name(root))  # type: ignore[arg-type]
            self.assigned_cache[key] = frozenset(names)
        return self.assigned_cache[key]

    def guard(self, cond: Node, branch: Node) -> Guard:
        return (id(cond), frozenset(names_in(cond)), branch, frozenset(self.tested(cond)))

    def tested(self, cond: Node) -> Iterable[str]:
        """The source text of the values a condition tests: each side of a comparison that is
        not a literal, each operand of `&&`, `||` and `!` that is no comparison."""
        stack = [cond]
        while stack:
            node = stack.pop()
            if isinstance(node, Tree) and node.data == "unary" and operator(node) == "!":
                stack.append(operand(node))
            elif isinstance(node, Tree) and node.data == "binary":
                left, op, right = binary_parts(node)
                if op in ("&&", "||", "^^"):
                    stack += [left, right]
                elif op in _COMPARISONS or op == "!=":
                    sides = (left, right)
                    yield from (self.source(side) for side in sides if not _is_literal(side))
                else:
                    yield self.source(node)
            elif not _is_literal(node):
                yield self.source(node)

    def source(self, node: Node) -> str:
        if isinstance(node, Token):
            return str(node)
        if node.meta.empty:
            return ""
        return "".join(self.text[node.meta.start_pos : node.meta.end_pos].split())

    def guarded(self, cond: Node, branch: Node, state: State) -> State | None:
        """A branch under a condition: its writes and reads remember the condition."""
        self.guards.append(self.guard(cond, branch))
        mark = self.known.mark()
        try:
            return self.nested(branch, state)
        finally:
            self.guards.pop()
            self.known.drop_since(mark)

    def block(self, items: list[Node], state: State | None) -> State | None:
        """A statement list in a scope of its own; iterative, so long bodies are fine."""
        self.scopes.append({})
        index = 0
        while index < len(items):
            if state is None:
                break  # the rest is unreachable and not analysed
            run = _case_run(items, index)
            if run > 1:
                state = self.cases(items[index : index + run], state)
                index += run
                continue
            state = self.statement(items[index], state)
            index += 1
        self.pop_scope()
        return state

    def pop_scope(self) -> None:
        """The end of a scope: the values of the names it declared go with it (an outer
        variable of the same name is not known again, which is only quieter)."""
        for name in self.scopes.pop():
            self.known.drop(name)

    def cases(self, ifs: list[Node], state: State) -> State | None:
        """`if (n == 0) ...; if (n == 1) ...; if (n == 2) ...;`: a case analysis, as a switch
        over the cases it names (one runs, from the state before them all)."""
        ends: list[State | None] = []
        for node in ifs:
            assert isinstance(node, Tree)
            self.expr(first_child(node), state)  # every condition runs
        for node in ifs:
            assert isinstance(node, Tree)
            cond, then, _ = if_parts(node)
            ends.append(self.guarded(cond, then, dict(state)))
        return _join(ends)

    def nested(self, node: Node, state: State) -> State | None:
        """A statement that forms a scope of its own (an if branch, a loop body)."""
        return self.block([node], state)

    def statement(self, node: Node, state: State) -> State | None:
        if not isinstance(node, Tree):
            return state
        kind = node.data
        if kind == "compound_statement":
            return self.block(node.children, state)  # its statements
        if kind == "declaration_statement":
            decl = first_child(node)
            if isinstance(decl, Tree) and decl.data == "variable_declaration":
                self.declaration(decl, state)
            return state
        if kind == "expression_statement":
            expr = first_child(node)
            self.expr(expr, state)
            if isinstance(expr, Tree) and expr.data == "assignment":
                target, op, value = binary_parts(expr)
                name = variable_name(target)
                # a local or parameter: a global may change in any call
                if op == "=" and name is not None and any(name in s for s in self.scopes):
                    self.known.store(name, value)
            return state
        if kind == "if_statement":
            cond, then_branch, otherwise = if_parts(node)
            if id(node) not in self.chains:
                self.mark_chain(node)
            yes, no = self.condition(cond, state)
            if yes is not None and no is not None and id(node) not in self.taken:
                self.sweep(node, cond, then_branch)
            then = self.guarded(cond, then_branch, yes) if yes is not None else None
            sweep = self.taken.get(id(node))
            if sweep is not None and then is not None:
                sweep.taken.setdefault(id(node), []).append(dict(then))
            other = no
            if otherwise is not None and no is not None:
                if isinstance(otherwise, Tree) and otherwise.data == "if_statement":
                    # `else if`: an if declares nothing, so it needs no scope of its own; one
                    # per link made a long else-if chain as deep in scopes as it is long, and
                    # every name lookup walked them all (quadratic in the chain's length).
                    self.guards.append(self.guard(cond, otherwise))
                    try:
                        other = self.statement(otherwise, no)
                    finally:
                        self.guards.pop()
                else:
                    other = self.guarded(cond, otherwise, no)
            elif self.chains[id(node)]:
                other = None  # the last case of an exhaustive chain: no path skips them all
            return _join([then, other])
        if kind == "for_statement":
            return self.for_loop(node, state)
        if kind == "while_statement":
            return self.while_loop(node, state)
        if kind == "do_statement":
            return self.do_loop(node, state)
        if kind == "switch_statement":
            return self.switch(node, state)
        if kind == "jump_statement":
            return self.jump(node, state)
        return state  # empty statements, stray labels

    def mark_chain(self, head: Tree) -> None:
        """Note each link of an else-if chain, and whether the chain is a case analysis: at
        least `_CASES` comparisons of one value and no final else."""
        links = [head]
        while (last := if_parts(links[-1])[2]) is not None:
            if not (isinstance(last, Tree) and last.data == "if_statement"):
                break
            links.append(last)
        exhaustive = if_parts(links[-1])[2] is None and _one_value([first_child(c) for c in links])
        for link in links:
            self.chains[id(link)] = exhaustive and link is links[-1]

    def declaration(self, decl: Tree, state: State) -> None:
        view = VariableDeclaration(decl)
        type_name, type_array = type_of_declaration(view.type.syntax)
        for declarator in view.declarators:
            name = declarator.name_token
            is_array = type_array or declarator.array is not None
            init = declarator.initializer
            if init is not None:
                self.expr(init, state)  # the name's scope starts after its initialiser
                self.scopes[-1][str(name)] = None
                if is_array:
                    self.known.drop(str(name))
                else:
                    self.known.store(str(name), init)
                self.flag_set(str(name), _is_true(init), state)
                continue
            self.known.drop(str(name))
            width, fields = self.shape(type_name, is_array)
            var = Var(str(name), name, width, "local", fields, len(self.guards))  # type: ignore[arg-type]
            var.struct = type_name if fields else ""
            self.scopes[-1][var.name] = var
            state[id(var)] = 0
            self.flag_set(var.name, False, state)
            for flag, names in self.flag_names.items():
                if var.name in names and flag != var.name:
                    promise = Var(f"{flag}|{var.name}", name, width, "local", fields)  # type: ignore[arg-type]
                    self.promises.setdefault(flag, []).append((var, promise))
                    self.promised.setdefault(id(var), []).append(promise)
                    state[id(promise)] = 0

    def flags(self, body: Tree) -> dict[str, frozenset[str]]:
        """The names tested bare as conditions (`if (hit)`, `if (!hit)`) in a function, with the
        names their branches assign."""
        found: dict[str, frozenset[str]] = {}
        for node in walk_kind(body, "if_statement"):
            cond, then, otherwise = if_parts(node)
            if isinstance(cond, Tree) and cond.data == "unary" and operator(cond) == "!":
                cond = operand(cond)
            name = variable_name(cond)
            if name is not None:
                names = self.assigned(then)
                if otherwise is not None:
                    names |= self.assigned(otherwise)
                found[name] = found.get(name, frozenset()) | names
        return found

    def flag_set(self, name: str, true: bool, state: State) -> None:
        """A flag is given a value: where it is `true` every promise tied to it holds; any
        other value keeps only what is written."""
        for var, promise in self.promises.get(name, ()):
            if id(promise) in state:
                state[id(promise)] = promise.full if true else state.get(id(var), 0)

    def flag_false(self, node: Node, state: State) -> None:
        """Where a tested flag is false, a promise tied to it is what is written."""
        name = variable_name(node)
        if name is None or not any(name in scope for scope in self.scopes):
            return  # a global: a call may change it
        for var, promise in self.promises.get(name, ()):
            if id(var) in state and id(promise) in state:
                state[id(var)] |= state[id(promise)]

    def jump(self, node: Tree, state: State) -> State | None:
        jump = JumpStatement(node)
        word = jump.keyword
        if word == "return":
            value = jump.value
            if value is not None:
                self.expr(value, state)
            assert self.flow is not None
            self.flow.exits.append(Exit(node, dict(state)))
        elif word in ("break", "continue"):
            loop = word == "continue"
            for target in reversed(self.targets):
                if target.loop or not loop:
                    (target.continues if loop else target.breaks).append(dict(state))
                    break
        # discard ends the invocation: nothing after it is observed, so nothing is owed.
        return None

    def for_loop(self, node: Tree, state: State) -> State | None:
        init, cond, step, body = for_parts(node)
        self.scopes.append({})
        clock = self.known.clock
        after: State | None = self.statement(init, state)
        if after is None:
            self.pop_scope()
            return None
        enter: State | None = after
        leave: State | None = None  # no condition: only `break` leaves
        surely = cond is None
        if cond is not None:
            # the first test, with the values set before the loop (`i = 0`, `t = 0.0`)
            self.asking += 1
            enter, leave = self.condition(cond, after)
            self.asking -= 1
            surely = enter is not None and (leave is None or self.runs_once(init, cond))
            if surely:
                leave = None
        target = _Target(loop=True)
        self.targets.append(target)
        start = _loop_start(init)
        counted = start is not None and not _assigns(body, start[0])
        peel = surely and enter is not None and self.peels < _PEELS
        if peel and enter is not None:
            # A loop that surely runs, in two passes: the first iteration, where the counter
            # is its start (`if (i == 0) first = q; else use(prev);`) and the values set
            # before the loop hold until the body changes them (`if (h < eps) break;` with
            # h = 1.0 does not break), then the later ones from the state the first leaves
            # (`prev = q` at its end), where they do not.
            first = self.number(start[1]) if counted and start is not None else None
            if counted and start is not None:
                self.counters.append((start[0], first, True))
                values = self.counter_values(start, cond, step)
                where = len(self.guards), len(self.targets)
                self.sweeps.append(_Sweep(node, start[0], values, *where, clock))
            self.peels += 1  # until the second pass ends: nested peels cost at most 4 times
            self.asking += 1
            end = self.nested(body, dict(enter))
            self.asking -= 1
            if counted:
                self.counters.pop()
            enter = _join([end, *target.continues])
            target.continues.clear()
            if enter is not None and step is not None:
                self.expr(step, enter)
            self.forget(node)
            if enter is not None and cond is not None:
                enter = self.condition(cond, enter)[0]
            if counted and start is not None:
                self.counters.append((start[0], first, False))
                self.sweeps[-1].first = False
        self.forget(node)
        end = self.nested(body, dict(enter)) if enter is not None else None
        # what the body stored does not hold where a `continue` or `break` left it, nor after
        self.forget(node)
        sweep = None
        if peel:
            self.peels -= 1
            if counted:
                self.counters.pop()
                sweep = self.sweeps.pop()
        self.targets.pop()
        looped = _join([end, *target.continues])
        if looped is not None and step is not None:
            self.expr(step, looped)
        again: State | None = None  # leaving after some iterations: looped ⊇ after, but a
        if looped is not None and cond is not None:  # loop that surely runs has no `after`
            _, again = self.condition(cond, looped)
        self.pop_scope()
        result = _join([leave, again, *target.breaks])
        if sweep is not None and sweep.taken:
            # a branch the search surely takes on some iteration: what it writes is written
            # when the loop ends (on every iteration it runs from one of these states)
            for key in sweep.taken:
                self.taken.pop(key, None)
            if result is not None:
                for states in sweep.taken.values():
                    written = _join(states) or {}
                    for var, mask in written.items():
                        if var in result:
                            result[var] |= mask
        return result

    def counter_values(
        self, start: tuple[str, Node], cond: Node | None, step: Node | None
    ) -> tuple[float, ...] | None:
        """The values a counter takes, `for (int i = -1; i <= 1; i++)` -> (-1, 0, 1): a
        constant start and bound and a constant step; a long run by its ends and its middle
        (any value it takes will do). None when they are not known."""
        name, first = start
        a, delta = self.number(first), _step(step, name)
        if a is None or a[0] != a[1] or delta is None or delta == 0:
            return None
        if not (isinstance(cond, Tree) and cond.data == "binary"):
            return None
        left, op, right = binary_parts(cond)
        if _is_variable(right, name) and op in _FLIP:
            left, op, right = right, _FLIP[op], left
        b = self.number(right)
        if not _is_variable(left, name) or b is None or b[0] != b[1] or op not in _FLIP:
            return None
        checks = {"<": float.__lt__, "<=": float.__le__, ">": float.__gt__, ">=": float.__ge__}
        if op not in checks:
            return None
        count = (b[0] - a[0]) / delta
        if not 0 <= count <= 1e6:
            return None
        values = [a[0] + k * delta for k in range(int(count) + 2)]
        values = [v for v in values if checks[op](float(v), float(b[0]))]
        if len(values) > _SWEEP:
            values = [values[0], values[len(values) // 2], values[-1]]
        return tuple(values) or None

    def sweep(self, node: Tree, cond: Node, branch: Node) -> None:
        """Whether the search loops around `if (d < md)` surely take it on some iteration: the
        if stands directly in their bodies, which neither break nor continue, `md` changes in
        them only in the branch, and for some values of their counters the known values
        (those set in the body on that iteration, the counters', `md`'s from before the loops,
        the model's ranges for the rest) make the condition true. Until `md` is first lowered
        it keeps its first value, so the branch runs at that iteration or before."""
        if not (self.asking and self.sweeps and isinstance(cond, Tree) and cond.data == "binary"):
            return
        left, op, right = binary_parts(cond)
        if op not in ("<", "<=", ">", ">="):
            return
        bounds = [variable_name(side) for side in (left, right)]
        depth, targets = len(self.guards), len(self.targets)
        chosen: list[_Sweep] = []
        for sweep in reversed(self.sweeps):
            # directly in the loop's body: no branch, loop or switch between
            if (sweep.depth, sweep.targets) != (depth, targets):
                break
            if not sweep.first or sweep.values is None or _jumps(sweep.loop):
                break
            chosen.append(sweep)
            targets -= 1  # the enclosing loop's body holds this loop directly
        for count in range(1, len(chosen) + 1):
            loops = chosen[:count]
            outer = loops[-1]
            for bound in bounds:
                if bound is None or not self.only_in(outer.loop, bound, branch):
                    continue
                if self.holds_somewhere(cond, loops, bound):
                    self.taken[id(node)] = outer
                    return

    def only_in(self, loop: Tree, name: str, branch: Node) -> bool:
        """Whether every write of `name` in the loop lies in `branch`."""
        writes = self.loop_writes.get(id(loop))
        if writes is None:
            writes = self.loop_writes[id(loop)] = _write_positions(loop)
        if not isinstance(branch, Tree) or branch.meta.empty:
            return False
        lo, hi = branch.meta.start_pos, branch.meta.end_pos
        return all(lo <= at < hi for at in writes.get(name, ()))

    def holds_somewhere(self, cond: Node, loops: list[_Sweep], bound: str) -> bool:
        """Whether the condition holds for some values of the loops' counters (at most
        `_SWEEP` squared tries, each a bounded question)."""
        outer = loops[-1]
        names = self.loop_names.get(id(outer.loop))
        if names is None:
            names = self.loop_names[id(outer.loop)] = _written_names(outer.loop)
        counters = {sweep.counter for sweep in loops}
        # a value stored before the loops holds on their first iteration only: the model's
        # ranges (which hold on every run) answer for it, but for the bound
        hidden = {n for n in names - counters - {bound} if self.known.stored_before(n, outer.clock)}
        tries: list[dict[str, float]] = [{}]
        for sweep in loops:
            assert sweep.values is not None
            tries = [{**t, sweep.counter: v} for t in tries for v in sweep.values]
        return any(self.known.truth(cond, values, hidden) is True for values in tries)

    def forget(self, loop: Tree) -> None:
        """The iterations after the first: the values the loop may change are not known."""
        names = self.loop_names.get(id(loop))
        if names is None:
            names = self.loop_names[id(loop)] = _written_names(loop)
        for name in names:
            self.known.drop(name)

    def runs_once(self, init: Node, cond: Node) -> bool:
        """Whether a counted loop certainly runs its body: `for (int i = A; i < B; ...)`, with
        A and B int or float constants, const variables or anything else whose value ranges
        compare (`for (float i = 1.5; i > 0.; i -= .002)`, `i < iterations`)."""
        start = _loop_start(init)
        if start is None or not (isinstance(cond, Tree) and cond.data == "binary"):
            return False
        left, op, right = binary_parts(cond)
        if _is_variable(right, start[0]) and op in _FLIP:
            left, op, right = right, _FLIP[op], left
        if not _is_variable(left, start[0]) or op not in _FLIP:
            return False
        a, b = self.number(start[1]), self.number(right)
        if a is None or b is None:
            return False
        (a_lo, a_hi), (b_lo, b_hi) = a, b
        checks = {"<": a_hi < b_lo, "<=": a_hi <= b_lo, ">": a_lo > b_hi,
                  ">=": a_lo >= b_hi, "!=": a_hi < b_lo or a_lo > b_hi}  # fmt: skip
        return checks[op]

    def number(self, node: Node) -> tuple[float, float] | None:
        """The range of a loop bound: an int constant of this file, else the value ranges."""
        value = _int_value(node)
        name = variable_name(node) if value is None else None
        if name is not None:
            value = self.consts.get(name)
        if value is not None:
            return value, value
        return self.model.range(node) if self.model is not None else None

    def while_loop(self, node: Tree, state: State) -> State | None:
        loop = WhileStatement(node)
        cond, body = loop.condition, loop.body
        self.scopes.append({})
        declared = loop.declaration
        if declared is not None:
            self.expr(declared.initializer, state)
            self.scopes[-1][declared.name] = None
            enter, leave = state, dict(state)
        else:
            # the first test, with the values set before the loop
            self.asking += 1
            enter, leave = self.condition(cond, state)
            self.asking -= 1
        target = _Target(loop=True)
        self.targets.append(target)
        self.forget(node)
        # writes in the body only strengthen later tests: the first test's state is the exit's,
        # unless the first test surely passes: then the loop leaves by a later one
        end = self.nested(body, dict(enter)) if enter is not None else None
        self.forget(node)
        self.targets.pop()
        again: State | None = None
        looped = _join([end, *target.continues])
        if leave is None and looped is not None:
            again = self.condition(cond, looped)[1]
        self.pop_scope()
        return _join([leave, again, *target.breaks])

    def do_loop(self, node: Tree, state: State) -> State | None:
        loop = DoStatement(node)
        body, cond = loop.body, loop.condition
        target = _Target(loop=True)
        self.targets.append(target)
        self.forget(node)
        end = self.nested(body, dict(state))
        self.forget(node)
        self.targets.pop()
        looped = _join([end, *target.continues])
        leave = self.condition(cond, looped)[1] if looped is not None else None
        return _join([leave, *target.breaks])

    def switch(self, node: Tree, state: State) -> State | None:
        switch = SwitchStatement(node)
        self.expr(switch.selector, state)
        target = _Target(loop=False)
        self.targets.append(target)
        self.scopes.append({})
        current: State | None = None
        has_default = False
        mark = self.known.mark()
        for item in switch.body:
            if isinstance(item, Tree) and item.data in ("case_label", "default_label"):
                has_default = has_default or item.data == "default_label"
                current = _join([current, state])  # entered from the switch, or fallen into
                self.known.drop_since(mark)  # what one case stored does not hold in the next
                continue
            if current is not None:
                current = self.statement(item, current)
        self.known.drop_since(mark)
        self.pop_scope()
        self.targets.pop()
        return _join([current, *target.breaks, None if has_default else state])

    # --- expressions --------------------------------------------------------------------------

    def lookup(self, name: str) -> Var | None:
        for scope in reversed(self.scopes):
            if name in scope:
                return scope[name]
        return None

    def expr(self, node: Node, state: State) -> None:
        """Evaluate an expression: check its reads, record its writes, in evaluation order."""
        if not isinstance(node, Tree):
            return
        kind = node.data
        if kind in ("binary", "sequence"):
            self.chain(node, state)
        elif kind in ("variable", "field", "index"):
            self.read(node, state)
        elif kind == "assignment":
            target, op, value = binary_parts(node)
            self.indices(target, state)
            rest = _clearing(target, op, value)
            if rest is not None:  # `O -= O`, `o = o*0. - d`: the old value does not matter
                if not isinstance(rest, bool):
                    self.expr(rest, state)
                self.write(target, state)
                return
            if op != "=":
                self.read(target, state, indices=False)
            self.expr(value, state)
            self.write(target, state)
            if op == "=" and self.promises and _is_true(value):
                self.flag_set(variable_name(target) or "", True, state)
        elif kind in ("prefix", "postfix"):
            target = operand(node)
            self.read(target, state)
            self.write(target, state)
        elif kind == "ternary":
            ternary = Ternary(node)
            cond, yes, no = ternary.condition, ternary.if_true, ternary.if_false
            on_true, on_false = self.condition(cond, state)
            a = dict(on_true) if on_true is not None else None
            b = dict(on_false) if on_false is not None else None
            self.guards.append(self.guard(cond, node))
            try:
                if a is not None:
                    self.expr(yes, a)
                if b is not None:
                    self.expr(no, b)
            finally:
                self.guards.pop()
            state.update(_join([a, b]) or {})
        elif kind == "call":
            self.call(node, state)
        else:  # constructors, unary operators, literals
            for child in node.children:
                if isinstance(child, Tree) and child.data != "type_specifier":
                    self.expr(child, state)

    def condition(self, node: Node, state: State) -> tuple[State | None, State | None]:
        """Evaluate a condition: the states where it is true and where it is false (None: it
        cannot be). Inside `a && b` being true, b ran; `a || b` false ran both; a comparison
        the value ranges decide leaves one side only. Mutates `state` (its first operand runs
        on every path); the true state may be `state` itself."""
        if isinstance(node, Tree) and node.data == "unary" and operator(node) == "!":
            no, yes = self.condition(operand(node), state)
            return self.decided(node, yes, no)
        if not (isinstance(node, Tree) and node.data == "binary"
                and operator(node) in ("&&", "||")):  # fmt: skip
            self.expr(node, state)
            yes, no = self.decided(node, state, dict(state))
            if no is not None and self.promises:
                self.flag_false(node, no)
            return yes, no
        op = operator(node)
        spine = [node]  # `a && b && c` parses ((a && b) && c): walk the left spine iteratively
        first: Node = first_child(node)
        while (isinstance(first, Tree) and first.data == "binary"
               and operator(first) == op):  # fmt: skip
            spine.append(first)
            first = first_child(first)
        operands = [first, *(binary_parts(link)[2] for link in reversed(spine))]
        current: State | None = state
        others: list[State | None] = []  # the states that decide the chain early
        for part in operands:
            if current is None:
                break  # decided before this operand: it does not run
            yes, no = self.condition(part, current)
            current, other = (yes, no) if op == "&&" else (no, yes)
            others.append(other)
        decided = _join(others)
        yes, no = (current, decided) if op == "&&" else (decided, current)
        return self.decided(node, yes, no)

    def decided(
        self, node: Node, yes: State | None, no: State | None
    ) -> tuple[State | None, State | None]:
        """Drop the side of a condition that the value ranges say cannot happen."""
        truth = self.counter_truth(node)
        if truth is None and self.asking:
            truth = self.known.truth(node)
        if truth is None and self.model is not None:
            truth = self.model.truth(node)
        if truth is None and _is_true(node):
            truth = True
        if truth is True:
            return yes, None
        if truth is False:
            return None, no
        return yes, no

    def counter_truth(self, node: Node) -> bool | None:
        """A comparison of a peeled loop's counter with its start value: decided in the first
        iteration (the counter is the start) and for `==`/`!=` in the later ones (it is not)."""
        if not (self.counters and isinstance(node, Tree) and node.data == "binary"):
            return None
        left, op, right = binary_parts(node)
        for name, first, is_first in reversed(self.counters):
            if _is_variable(right, name) and op in _FLIP:
                left, op, right = right, _FLIP[op], left
            if not _is_variable(left, name):
                continue
            value = self.number(right)
            if first is None or value is None or first[0] != first[1] or value[0] != value[1]:
                return None
            a, b = first[0], value[0]
            if is_first:
                checks = {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b, "==": a == b,
                          "!=": a != b}  # fmt: skip
                return checks.get(op)
            if a == b and op in ("==", "!="):
                return op == "!="
            return None
        return None

    def chain(self, node: Tree, state: State) -> None:
        """Binary operators and sequences; left-deep chains (`a + b + c + ...`) are walked
        iteratively. The right side of && and || may not run, so its writes are dropped."""
        rights: list[tuple[Node, bool]] = []
        while isinstance(node, Tree) and node.data in ("binary", "sequence"):
            if node.data == "binary":
                left, op, right = binary_parts(node)
                rights.append((right, op in _SHORT_CIRCUIT))
            else:
                sequence = Sequence(node)
                left = sequence.left
                rights.append((sequence.right, False))
            node = left
        self.expr(node, state)
        for right, maybe in reversed(rights):
            self.expr(right, dict(state) if maybe else state)

    def call(self, node: Tree, state: State) -> None:
        callee = Call(node).callee
        args = call_arguments(node)
        if isinstance(callee, Tree) and callee.data == "field":
            if field_name(callee) == "length":
                return  # `a.length()` reads no element of `a`
            self.expr(callee, state)
        name = variable_name(callee) or ""
        qualifiers = self.qualifiers(name, len(args))
        callee = self.summaries.get((name, len(args))) if name in self.signatures else None
        summary = None if callee is None else callee.inout_reads
        origins = None if callee is None else callee.origins
        written = []
        for position, (arg, qualifier) in enumerate(zip(args, qualifiers, strict=True)):
            lvalue = _root(arg) is not None
            part = None if summary is None else summary[position]
            whole = isinstance(arg, Tree) and arg.data == "variable"
            if qualifier == "in" and whole and part is not None:
                # a struct passed in: only the members the callee reads are read
                self.read(arg, state, part=part, origins=origins[position] if origins else None)
            elif qualifier == "in" or not lvalue:
                self.expr(arg, state)
            elif qualifier == "inout":
                # the callee's summary: which components it may read before writing them
                where = origins[position] if origins else None
                self.read(arg, state, part=part, origins=where)
                written.append(arg)
            else:  # out, or a function this file does not define: a write, never a read
                self.indices(arg, state)
                written.append(arg)
        for arg in written:
            self.write(arg, state)

    def qualifiers(self, name: str, count: int) -> list[str]:
        """How a call passes each argument: in, out, inout, or ? (unknown function)."""
        if name in self.signatures:
            options = [q for q in self.signatures[name] if len(q) == count]
            if not options:
                return ["?"] * count
            # overloads that pass a position differently leave it unknown
            return [options[0][i] if len({q[i] for q in options}) == 1 else "?"
                    for i in range(count)]  # fmt: skip
        if name in _BUILTIN_QUALIFIERS and count == len(_BUILTIN_QUALIFIERS[name]):
            return list(_BUILTIN_QUALIFIERS[name])
        if name in BUILTIN_FUNCTIONS:
            return ["in"] * count
        return ["?"] * count  # defined elsewhere (another snippet, the Common tab)

    def access(self, node: Node) -> tuple[Var | None, tuple[int, ...] | None]:
        """The tracked variable an lvalue-like expression reads or writes, and which of its
        components (None: the whole variable, or components we cannot tell)."""
        path: list[Tree] = []
        while isinstance(node, Tree) and node.data in ("field", "index"):
            path.append(node)
            node = first_child(node)
        name = variable_name(node)
        if name is None:
            return None, None
        var = self.lookup(name)
        if var is None:
            return None, None
        comps: tuple[int, ...] | None = tuple(range(var.width)) if var.width > 1 else None
        for step in reversed(path):
            if comps is None:
                break
            if var.fields:
                # a member, whatever is picked of it after (`s.pos.x` is part of `s.pos`)
                member = field_name(step) if step.data == "field" else ""
                in_whole = len(comps) == var.width and member in var.fields
                comps = (var.fields.index(member),) if in_whole else None
                break
            if step.data == "field":
                picked = swizzle(field_name(step), len(comps))
                comps = None if picked is None else tuple(comps[i] for i in picked)
            else:
                index = _int_value(index_expression(step))
                in_range = index is not None and 0 <= index < len(comps) and len(comps) > 1
                comps = (comps[index],) if in_range else None  # type: ignore[index]
        return var, comps

    def read(
        self,
        node: Node,
        state: State,
        indices: bool = True,
        part: int | None = None,
        origins: dict[int, Node] | None = None,
    ) -> None:
        """Check a read of `node`; `part`: only these of its components (by position in the
        expression's value: an inout argument whose callee reads `.zw` first); `origins`: by
        the same positions, where the callee reads them."""
        if indices:
            self.indices(node, state)
        var, comps = self.access(node)
        if var is None:
            return  # not tracked; `indices` evaluated whatever the chain starts from (`f().x`)
        where: dict[int, Node] = {}
        if part is not None and comps is not None:
            picked = [(i, c) for i, c in enumerate(comps) if part >> i & 1]
            comps = tuple(c for _, c in picked)
            if origins:
                where = {c: origins[i] for i, c in picked if i in origins}
        mask = var.full if comps is None else sum(1 << c for c in set(comps))
        if part == 0:
            mask = 0
        missing = mask & ~state.get(id(var), var.full)
        if missing and var.kind in ("inout", "in"):  # the function's summary, not a finding
            assert self.flow is not None
            position = self.inout_position[id(var)]
            self.flow.inout_reads[position] = (self.flow.inout_reads[position] or 0) | missing
            first = self.flow.origins[position]
            if first is not None:
                for c in range(var.width):
                    if missing >> c & 1 and c not in first:
                        first[c] = where.get(c, node)
        elif missing and id(node) not in self.reported:
            self.reported.add(id(node))
            assert self.flow is not None
            guards = tuple(self.guards[var.depth :])
            self.flow.reads.append(Read(var, node, missing, guards, where))
        if id(var) in state:
            state[id(var)] |= mask  # report a variable once per path, not at every later read

    def write(self, node: Node, state: State) -> None:
        root = _root(node)
        if root is not None:
            self.known.drop(variable_name(root))  # type: ignore[arg-type]
        var, comps = self.access(node)
        if var is not None and id(var) in state and var.kind in ("local", "out"):
            guards = tuple(self.guards[var.depth :])
            self.writes.setdefault(id(var), []).append((guards, guards[-1][2] if guards else None))
        if var is not None and id(var) in state:
            # a write the path cannot follow (`a[i] = `, `s.m = `) counts as a whole write
            bits = var.full if comps is None else sum(1 << c for c in set(comps))
            state[id(var)] |= bits
            for promise in self.promised.get(id(var), ()):
                if id(promise) in state:
                    state[id(promise)] |= bits
        if root is not None and self.promises:
            self.flag_set(variable_name(root) or "", False, state)  # true again only if `= true`

    def indices(self, node: Node, state: State) -> None:
        """Evaluate the index expressions inside an lvalue (`a[i + 1].x`): they are reads."""
        while isinstance(node, Tree) and node.data in ("field", "index"):
            if node.data == "index":
                self.expr(index_expression(node), state)
            node = first_child(node)
        if isinstance(node, Tree) and node.data not in ("variable",):
            self.expr(node, state)


def _compared(cond: Node) -> tuple[Node, ...]:
    """The sides of a comparison (`n == 2`, `t < t1`), or those that every comparison of an
    `||`/`&&` of comparisons shares (`id == 1 || id == 2` -> id); none for anything else."""
    if not (isinstance(cond, Tree) and cond.data == "binary"):
        return ()
    left, op, right = binary_parts(cond)
    if op in _COMPARISONS:
        return left, right
    if op in ("||", "&&"):
        lefts, rights = _compared(left), _compared(right)
        return tuple(a for a in lefts if any(same_expression(a, b) for b in rights))
    return ()


def _equalities(cond: Node) -> bool:
    """Whether a condition is `==` tests joined by `||` (`id == 1 || id == 2`)."""
    if not (isinstance(cond, Tree) and cond.data == "binary"):
        return False
    left, op, right = binary_parts(cond)
    if op == "||":
        return _equalities(left) and _equalities(right)
    return op == "=="


def _one_value(conds: list[Node]) -> bool:
    """Whether the conditions make a case analysis of one value: each compares a side shared by
    all of them, at least `_CASES` of them, or two when they test ids (`==` only)."""
    if len(conds) < (2 if all(map(_equalities, conds)) else _CASES):
        return False
    first = _compared(conds[0])
    return any(
        all(any(same_expression(side, value) for side in _compared(c)) for c in conds[1:])
        for value in first
        if not _is_literal(value)
    )


def _is_literal(node: Node) -> bool:
    return isinstance(node, Tree) and node.data in ("float_literal", "int_literal", "bool_literal")


def _case_run(items: list[Node], start: int) -> int:
    """How many statements from `start` are `if (v == c) ...` without else, for one value v
    (and each c a literal or a name): a case analysis of ids when there are at least two."""
    conds: list[Node] = []
    for item in items[start:]:
        if not (isinstance(item, Tree) and item.data == "if_statement"):
            break
        cond, _, otherwise = if_parts(item)
        if otherwise is not None:
            break
        if not (_compared(cond) and _equalities(cond)):
            break
        if conds and not _one_value([conds[0], cond]):
            break
        conds.append(cond)
    if len(conds) < 2:
        return 0
    # the value must stay the same through the cases
    values = [side for side in _compared(conds[0]) if not _is_literal(side)]
    roots = {variable_name(r) for r in map(_root, values) if r is not None}
    bodies = items[start : start + len(conds)]
    if any(_assigns(body, name) for body in bodies for name in roots):
        return 0
    return len(conds)


def _root(node: Node) -> Tree | None:
    """The variable at the root of an lvalue chain, or None if it is not an lvalue."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = first_child(node)
    return node if isinstance(node, Tree) and node.data == "variable" else None


def _is_zero(node: Node) -> bool:
    if isinstance(node, Tree) and node.data in ("float_literal", "int_literal"):
        text = token_text(node).rstrip("fFuU").lower()  # type: ignore[union-attr]
        try:
            return float(text) == 0.0 if not text.startswith("0x") else int(text, 16) == 0
        except ValueError:
            return False
    return False


def _cleared(expr: Node, target: Node) -> bool:
    """Whether `expr` is the target times zero or minus itself (`x*0.`, `0.*x`, `x - x`)."""
    if not (isinstance(expr, Tree) and expr.data == "binary"):
        return False
    left, op, right = binary_parts(expr)
    if op == "-":
        return same_expression(left, target) and same_expression(right, target)
    if op == "*":
        return (same_expression(left, target) and _is_zero(right)) or (
            _is_zero(left) and same_expression(right, target)
        )
    return False


def _clearing(target: Node, op: str, value: Node) -> Node | bool | None:
    """The golfing idioms that clear a variable before use (`O -= O`, `x *= 0.`, `x = x - x`,
    `o = o*0. - d`): its old value is multiplied by zero or cancelled, so the assignment is a
    write, not a read (only a NaN or an infinity in the old bits would survive). Returns what
    else the value reads (`d`), True when nothing, None when it is no such idiom."""
    if _root(target) is None:
        return None
    if op == "-=":
        return True if same_expression(value, target) else None
    if op == "*=":
        return True if _is_zero(value) else None
    if op != "=":
        return None
    if _cleared(value, target):
        return True
    if isinstance(value, Tree) and value.data == "binary":
        left, plus_minus, right = binary_parts(value)
        if plus_minus not in ("+", "-"):
            return None
        if _cleared(left, target):
            return right
        if plus_minus == "+" and _cleared(right, target):
            return left
    return None


def _is_true(node: Node) -> bool:
    return isinstance(node, Tree) and node.data == "bool_literal" and token_text(node) == "true"


_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "!=": "!="}


_WRITERS = ("assignment", "prefix", "postfix", "call")
_SWEEP = 9  # counter values tried per loop for a search's branch; a longer run by 3 of them
_PEELS = 2  # loops nested in one another analysed in two passes (each doubles its body's work)


def _written_names(node: Tree) -> frozenset[str]:
    """The names that `node` may write: assigned, incremented, or passed to a call (which may
    take it as `out`)."""
    names: set[str] = set()
    for kind in _WRITERS:
        for sub in walk_kind(node, kind):
            # a call may take its arguments as `out`
            targets = call_arguments(sub) if sub.data == "call" else [assigned_target(sub)]
            for target in targets:
                root = _root(target)
                if root is not None:
                    names.add(variable_name(root))  # type: ignore[arg-type]
    return frozenset(names)


def _write_positions(node: Tree) -> dict[str, list[int]]:
    """Where each name is written in `node` (as `_written_names`): name -> start positions."""
    found: dict[str, list[int]] = {}
    for kind in _WRITERS:
        for sub in walk_kind(node, kind):
            targets = call_arguments(sub) if sub.data == "call" else [assigned_target(sub)]
            for target in targets:
                root = _root(target)
                if root is not None and not sub.meta.empty:
                    name = variable_name(root)
                    found.setdefault(name, []).append(sub.meta.start_pos)  # type: ignore[arg-type]
    return found


def _jumps(loop: Tree) -> bool:
    """Whether a `break` or `continue` stands anywhere in the loop (one of an inner loop's
    too: simpler, and only quieter)."""
    jumps = walk_kind(loop, "jump_statement")
    return any(JumpStatement(sub).keyword in ("break", "continue") for sub in jumps)


def _step(step: Node | None, name: str) -> float | None:
    """How much `i++`, `i--`, `i += 2`, `i -= 0.5` add to the counter; None for anything else."""
    if not isinstance(step, Tree):
        return None
    if step.data in ("prefix", "postfix") and _is_variable(operand(step), name):
        op = operator(step)
        return 1.0 if op == "++" else -1.0 if op == "--" else None
    if step.data == "assignment":
        target, op, value = binary_parts(step)
        if not _is_variable(target, name) or op not in ("+=", "-="):
            return None
        if isinstance(value, Tree) and value.data in ("int_literal", "float_literal"):
            try:
                amount = float(token_text(value).rstrip("fFuU"))  # type: ignore[union-attr]
            except ValueError:
                return None
            return amount if op == "+=" else -amount
    return None


def _assigns(node: Node, name: str) -> bool:
    """Whether `name` may be assigned anywhere in `node` (an assignment, ++/--, or an argument
    that a call may write)."""
    if not isinstance(node, Tree):
        return False
    # The writers alone, sliced from the file's index kind by kind (the order does not matter
    # here): asked of every loop, walking the whole body each time cost the square of the
    # loops' nesting.
    writers = (sub for kind in _WRITERS for sub in walk_kind(node, kind))
    for sub in writers:
        if sub.data == "call":
            targets = call_arguments(sub)
        elif sub.data != "assignment" or _root(assigned_target(sub)) is not None:
            targets = [assigned_target(sub)]
        else:
            continue
        if any(_is_variable(_root(t) or t, name) for t in targets):
            return True
    return False


def _is_variable(node: Node, name: str) -> bool:
    return variable_name(node) == name


def _loop_start(init: Node) -> tuple[str, Node] | None:
    """(counter, first value's expression) of `int i = A;` or `i = A;`."""
    if not isinstance(init, Tree):
        return None
    if init.data == "declaration_statement":
        decl = DeclarationStatement(init).variables
        declarators = decl.declarators if decl is not None else []
        if len(declarators) == 1:  # `int i = 0, j = 1;` has no one counter
            (declarator,) = declarators
            value = declarator.initializer
            if value is not None and declarator.array is None:
                return declarator.name, value
    if init.data == "expression_statement":
        expr = first_child(init)
        if isinstance(expr, Tree) and expr.data == "assignment":
            target, op, value = binary_parts(expr)
            name = variable_name(target)
            if op == "=" and name is not None:
                return name, value
    return None
