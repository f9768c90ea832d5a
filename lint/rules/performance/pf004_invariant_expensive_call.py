"""PF004 invariant-expensive-call-in-loop."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass

from lark import Tree

from glint.compiler.glsl.ast import (
    CompoundStatement,
    ForStatement,
    binary_parts,
    first_child,
    for_parts,
    if_parts,
    jump_parts,
    leaf_text,
    operand,
    variable_name,
)

from ...analysis.functions import Function, functions
from ...analysis.invariance import (
    IMPURE,
    LOOPS,
    Flow,
    Program,
    declared_in,
    flow_of,
    is_fetch,
    region_parts,
    varying,
)
from ...analysis.syntax import call_args, call_name, names_in, root_var
from ...context import LintContext, Node, walk_kind
from ...finding import Finding
from .. import Rule, register
from ..lighting._common import short_text
from .pf002_loop_invariant_work import _enclosing_trips, _from_macro, _global_names, trip_count

# Expression nodes a hoisted value can be (statements and declarations are not).
_EXPRESSIONS = {"call", "binary", "unary", "constructor", "field", "index", "ternary"}

# Operations wasted per pixel (repeats beyond the first, times the cost estimate: a texture
# fetch counts 20) below which a finding is not worth a change.
WASTE = 40

# The least share of the loop's (or the function's) own work that the repeated pieces must
# make: three extra fetches next to four full renders of an AA loop change nothing.
SHARE = 1 / 50


class _Flows:
    """Each function's writes (`flow_of`), found when first asked: most functions of a
    raymarcher are distance helpers that fetch nothing and loop nowhere, and need none."""

    def __init__(self, prog: Program, fns: list[Function]) -> None:
        self._prog = prog
        self._fns = {id(fn): fn for fn in fns}
        self._done: dict[int, Flow] = {}

    def __getitem__(self, key: int) -> Flow:
        if key not in self._done:
            self._done[key] = flow_of(self._prog, self._fns[key].body)
        return self._done[key]


@dataclass
class _Site:
    runs: int  # how many times the function runs per pixel, at most
    caller: str | None  # the caller that makes it run that often
    call: Tree | None  # the call in that caller
    stated: bool = True  # every loop on the way states its trip count (no march)


def _key(fn: Function) -> str:
    """A function's identity among overloads: its name and its number of parameters."""
    return f"{fn.name}/{len(fn.param_order)}"


def _call_key(call: Tree) -> str:
    """The identity (as `_key` gives it) of the overload a call can reach."""
    return f"{call_name(call)}/{len(call_args(call))}"


def _runs(ctx: LintContext, up: dict[int, Tree], prog: Program, flows: _Flows) -> dict[str, _Site]:
    """How many times each function (by `_key`: overloads apart) runs per pixel, at most
    (mainImage once, another function the largest over its call sites of the caller's runs times
    the loops around the call that repeat it), with the call site that gives that count."""
    defined = {_key(f): f for f in functions(ctx)}
    sites: dict[str, list[tuple[Function, Tree]]] = {}
    for fn in defined.values():
        for node in walk_kind(fn.body, "call"):
            if (key := _call_key(node)) in defined and key != _key(fn):
                sites.setdefault(key, []).append((fn, node))
    result: dict[str, _Site] = {}

    def count(name: str, depth: int) -> int:
        if name in result:
            return result[name].runs
        result[name] = _Site(1, None, None)  # a guard against call cycles
        if name.startswith("mainImage/") or depth > 16:
            return 1
        best = _Site(1, None, None)
        for caller, call in sites.get(name, ()):
            latch = _latch(prog, flows, caller, call)
            runs = count(_key(caller), depth + 1) * _repeats(ctx, call, caller, up, latch)
            if runs > best.runs:
                stated = result[_key(caller)].stated and _stated(ctx, call, caller, up)
                best = _Site(min(runs, 1 << 30), _key(caller), call, stated)
        result[name] = best
        return best.runs

    for name in defined:
        count(name, 0)
    return result


def _stated(ctx: LintContext, node: Tree, fn: Function, up: dict[int, Tree]) -> bool:
    """Whether every loop of the function around the node states its trip count."""
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data in LOOPS and not trip_count(ctx, parent, fn, unknown=0):
            return False
        current = parent
    return True


def _loop_of_chain(sites: dict[str, _Site], name: str, up: dict[int, Tree]) -> Tree | None:
    """The innermost loop around the call that makes the function hot, following the chain of
    hottest callers up to the first call that sits in a loop."""
    seen: set[str] = set()
    while name in sites and name not in seen:
        seen.add(name)
        site = sites[name]
        if site.call is None or site.caller is None:
            return None
        node: Node = site.call
        while (parent := up.get(id(node))) is not None:
            if parent.data in LOOPS and not (
                parent.data == "for_statement" and ForStatement(parent).init is node
            ):
                return parent
            node = parent
        name = site.caller
    return None


def _fixed_globals(prog: Program, sites: dict[str, _Site], flows: _Flows) -> set[str]:
    """Globals that keep their value while any function runs repeatedly: written only by
    functions that run once per pixel, and there outside loops (`time = iTime * 0.5;` at the top
    of mainImage)."""
    moving: set[str] = set()
    for group in prog.defined.values():
        for fn in group:
            if sites.get(_key(fn), _Site(1, None, None)).runs > 1:
                moving |= fn.written & prog.globals  # every write of the body
                continue
            end = -1
            for loop in walk_kind(fn.body, *LOOPS):  # the outermost loops, in source order
                if loop.meta.start_pos >= end:
                    end = loop.meta.end_pos
                    moving |= {w.target for w in flows[id(fn)].within(loop.meta.start_pos, end)}
    return prog.globals - moving


def _span(loop: Tree) -> tuple[int, int]:
    """Where the parts of the loop that repeat are (a for's init is before them)."""
    first = region_parts(loop)[0]
    start = first.meta.start_pos if isinstance(first, Tree) and not first.meta.empty else None
    return (start if start is not None else loop.meta.start_pos + 1), loop.meta.end_pos


def _moving_in_loop(
    prog: Program, fn: Function, loop: Tree, flow: Flow, declarations: Counter[str]
) -> tuple[set[str], set[str]]:
    """The names that vary between the passes of the loop, and the names declared in it (fresh
    on every pass)."""
    start, end = _span(loop)
    writes = flow.within(start, end)
    inside = Counter(w.target for w in writes if w.declares)
    # a name declared in the loop that also names a variable outside it (a shadowed counter, a
    # parameter, a global) is taken as the outer one: varying if written
    declared = {n for n, k in inside.items() if declarations[n] == k}
    declared -= set(fn.params) | prog.globals
    seed = {w.target for w in writes if w.target[0] != "#" and w.target not in declared}
    seed |= flow.globals_written_within(start, end) | {IMPURE}
    return varying(seed, writes), declared


def _innermost_loop(node: Tree, fn: Function, up: dict[int, Tree]) -> Tree | None:
    """The innermost loop of the function around the node (a for-init is not in its loop)."""
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data in LOOPS and not (
            parent.data == "for_statement" and ForStatement(parent).init is current
        ):
            return parent
        current = parent
    return None


def _reads_outside_accumulators(prog: Program, body: Node, carried: set[str]) -> set[str] | None:
    """The names the loop body reads, leaving out each carried variable's own operand in its
    update (`d = min(d, E)`, `s += E`, `x = E`, `n++`); None when a call writes globals."""
    found: set[str] = set()
    stack: list[Node] = [body]
    while stack:
        node = stack.pop()
        if not isinstance(node, Tree):
            continue
        if node.data == "variable":
            found.add(leaf_text(node))
            continue
        if node.data == "call" and (name := call_name(node)) in prog.defined:
            if prog.global_writes(name):  # type: ignore[arg-type]
                return None
            found |= prog.global_reads(name)  # type: ignore[arg-type]
        if node.data in ("prefix", "postfix") and root_var(operand(node)) in carried:
            continue
        if node.data == "assignment" and (target := root_var(first_child(node))) in carried:
            lhs, op, rhs = binary_parts(node)
            found |= names_in(lhs) - {target}
            if op == "=" and call_name(rhs) in ("min", "max"):
                args = call_args(rhs)  # type: ignore[arg-type]
                rest = [a for a in args if variable_name(a) != target]
                stack += rest if len(rest) == len(args) - 1 else args
            else:
                stack.append(rhs)
            continue
        stack += node.children
    return found


@dataclass
class _Info:
    """What the candidate search knows of an expression: it reads nothing that varies, has no
    side effect, fetches or loops (sticky), calls something."""

    same: bool = True
    pure: bool = True
    sticky: bool = False
    calls: bool = False


def _pieces(
    prog: Program, flow: Flow, parts: list[Node], moving: set[str], sticky: bool = True
) -> list[Tree]:
    """The largest expressions under the parts (outside nested loops) that read nothing that
    varies and, with `sticky`, fetch or loop, and the nested loops none of whose writes vary;
    in source order. Linear: one pass up the tree, one down."""
    info: dict[int, _Info] = {}
    # up: children before parents; a nested loop is a leaf, judged by its writes
    order: list[Node] = []
    stack: list[Node] = list(parts)
    while stack:
        node = stack.pop()
        order.append(node)
        if isinstance(node, Tree) and node.data not in LOOPS:
            stack += node.children
    for node in reversed(order):
        if not isinstance(node, Tree):
            continue
        here = _Info()
        if node.data in LOOPS:
            start, end = node.meta.start_pos, node.meta.end_pos
            here.same = not any(w.target in moving for w in flow.within(start, end))
            here.same = here.same and not flow.exits_within(start, end)
            here.sticky = here.calls = True
            info[id(node)] = here
            continue
        if node.data == "variable":
            here.same = leaf_text(node) not in moving
            info[id(node)] = here
            continue
        children = node.children
        if node.data == "call":
            name = call_name(node)
            here.calls = name is not None and not name[:1].isupper()
            if name in prog.defined:
                reads = prog.global_reads(name)  # type: ignore[arg-type]
                here.same = not (reads & moving) and not prog.global_writes(name)  # type: ignore
                here.sticky = prog.function_sticky(name)  # type: ignore[arg-type]
            elif is_fetch(name):
                here.sticky = True
            if name is not None:  # the callee's name is not a variable read
                callee = first_child(node)
                children = [c for c in children if c is not callee]
        elif node.data in ("assignment", "prefix", "postfix"):
            here.pure = False
        for child in children:
            sub = info.get(id(child))
            if sub is not None:
                here.same &= sub.same
                here.pure &= sub.pure
                here.sticky |= sub.sticky
                here.calls |= sub.calls
        info[id(node)] = here
    found: list[Tree] = []
    down: list[Node] = list(reversed(parts))
    while down:
        node = down.pop()
        if not isinstance(node, Tree):
            continue
        here = info[id(node)]
        if node.data in LOOPS:
            if sticky and here.same:
                found.append(node)
            continue
        if node.data == "assignment":
            down.append(binary_parts(node)[2])  # the target is written, never hoisted
            continue
        if node.data in _EXPRESSIONS and here.same:
            if here.pure and (here.sticky if sticky else here.calls):
                found.append(node)
            continue
        down += reversed(node.children)
    return found


@register
class InvariantExpensiveCall(Rule):
    """Finds expensive work that gives the same result on every pass of a loop, or on every call
    of a function that runs many times per pixel, where compilers leave it in place: a texture
    fetch whose coordinate does not change, a call of the file's own function that fetches or
    loops with unchanged arguments, a whole inner loop (a march) that reads nothing that changes;
    and a counted loop whose body does not use its counter at all, so every pass computes the
    same thing.

    What counts as unchanged: a data-flow closure over the writes of the loop (or of the
    function): a variable written in the loop but declared outside it varies, and so does
    whatever is computed from it or written under a condition that reads it; parameters vary
    between the calls of a function, and globals that a function running more than once per
    pixel writes. The cost estimate counts a fetch as 20 operations, a loop as its trip count
    times its body, a call as its function's body; a finding needs at least 40 wasted operations
    per pixel (repeats beyond the first, times the cost). Pure arithmetic is left to PF002:
    compilers hoist it themselves; implicit-derivative fetches and loops they do not.

    Why is this bad?
        A march runs its distance function up to hundreds of times per pixel; a fetch of a fixed
        texel or an inner loop with fixed inputs in it is paid on every step, where one
        evaluation before the loop gives the same value. A loop whose body ignores its counter
        does the work of one pass many times, and usually means the body lost its use of the
        counter in an edit (a per-sample offset, a per-cell seed).

    Example:
        float map(vec3 p) {
            float level = textureLod(iChannel0, vec2(0.5, 0.1), 0.0).x;
            return length(p) - 1.0 - level;
        }

    Use instead:
        float level;  // set once in mainImage before the march
        float map(vec3 p) { return length(p) - 1.0 - level; }

    Fix safety:
        No fix: the value needs a name, a type and a place before the loop (or in the caller).

    References:
        - Muchnick, Advanced Compiler Design and Implementation, 1997, §13.2 (Loop-Invariant Code
          Motion)
    """

    code = "PF004"
    name = "invariant-expensive-call-in-loop"
    category = "performance"
    severity = "info"
    default = True

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if not any(ctx.nodes(kind) for kind in LOOPS):
            return  # without a loop nothing runs more than once per pixel
        _, other_globals = _global_names(ctx)
        fns = functions(ctx)
        overloads: dict[str, list[Function]] = {}
        for f in fns:
            overloads.setdefault(f.name, []).append(f)
        prog = Program(ctx, overloads, other_globals, lambda loop, fn: trip_count(ctx, loop, fn))
        up = ctx.parents()
        flows = _Flows(prog, fns)
        sites = _runs(ctx, up, prog, flows)
        fixed = _fixed_globals(prog, sites, flows)
        self._reported: list[tuple[int, int]] = []
        # what varies in every loop first: the calls in a loop tell which parameters of the
        # called function change between its calls there
        self._loops: dict[int, tuple[set[str], set[str]]] = {}
        self._calls: dict[str, list[tuple[Function, Tree]]] = {}
        loops_of: dict[int, list[Tree]] = {}
        for fn in fns:
            for call in walk_kind(fn.body, "call"):
                if call_name(call) in overloads and (key := _call_key(call)) != _key(fn):
                    self._calls.setdefault(key, []).append((fn, call))
            loops_of[id(fn)] = walk_kind(fn.body, *LOOPS)
            if not loops_of[id(fn)]:
                continue
            flow = flows[id(fn)]
            declarations = Counter(w.target for w in flow.writes if w.declares)
            for loop in loops_of[id(fn)]:
                self._loops[id(loop)] = _moving_in_loop(prog, fn, loop, flow, declarations)
        for fn in fns:
            runs = sites.get(_key(fn), _Site(1, None, None)).runs
            loops = sorted(loops_of[id(fn)], key=lambda n: n.meta.start_pos)
            for index, loop in enumerate(loops):
                if self._covered(loop):
                    continue
                innermost = index + 1 == len(loops) or (
                    loops[index + 1].meta.start_pos >= loop.meta.end_pos
                )
                yield from self._loop(ctx, prog, fn, flows[id(fn)], loop, runs, up, innermost)
        for fn in fns:
            if sites.get(_key(fn), _Site(1, None, None)).runs >= 2 and _may_stick(prog, fn):
                yield from self._function(ctx, prog, fn, flows[id(fn)], sites, fixed, up)

    def _covered(self, node: Tree) -> bool:
        start, end = node.meta.start_pos, node.meta.end_pos
        return any(a <= start and end <= b for a, b in self._reported)

    def _mark(self, node: Tree) -> None:
        self._reported.append((node.meta.start_pos, node.meta.end_pos))

    # --- a loop's body ----------------------------------------------------------------------

    def _loop(
        self,
        ctx: LintContext,
        prog: Program,
        fn: Function,
        flow: Flow,
        loop: Tree,
        runs: int,
        up: dict[int, Tree],
        innermost: bool,
    ) -> Iterator[Finding]:
        trips = trip_count(ctx, loop, fn)
        if trips < 2:
            return
        parts = region_parts(loop)
        moving, declared = self._loops[id(loop)]
        line = ctx.span(loop)[0]
        if innermost:
            pointless = self._pointless(ctx, prog, flow, loop, declared, trips, moving)
            if pointless is not None:
                yield pointless
                return
        outside = runs * _enclosing_trips(ctx, loop, fn, up)
        found: list[tuple[Tree, int]] = []
        share = 0
        for node in _pieces(prog, flow, parts, moving):
            if self._covered(node) or id(loop) in _loops_left(node, fn, up):
                continue
            inside = runs * _enclosing_trips(ctx, node, fn, up)
            cost = prog.cost(node, fn)
            found.append((node, (inside - outside) * cost))
            share += inside // max(1, outside) * cost
        if not found or share < SHARE * prog.cost(loop, fn):
            return
        yield from self._group(
            ctx,
            found,
            f"every pass of the loop at line {line}",
            "it reads only {}, which the loop does not change",
            f"once before the loop at line {line}",
        )

    def _group(
        self, ctx: LintContext, found: list[tuple[Tree, int]], every: str, reads: str, where: str
    ) -> Iterator[Finding]:
        """One finding for the invariant work of a region, at its first piece, when the
        repeats waste enough. `reads` has a {} for the names the piece reads."""
        if not found or sum(waste for _, waste in found) < WASTE:
            return
        for node, _ in found:
            self._mark(node)
        node = found[0][0]
        inputs = _inputs(node) or "constants"
        if node.data in LOOPS:
            what, verb, fix = "this inner loop", "computes the same result", "run it"
        else:
            what = f"`{short_text(ctx, node, 60)}`{_from_macro(ctx, node)}"
            verb = "gives the same value"
            fix = "do the fetch" if _fetches(node) else "make the call"
        more = ""
        if len(found) > 1:
            lines = ", ".join(str(n) for n in sorted({ctx.span(n)[0] for n, _ in found[1:]}))
            plural = "s" if len(found) > 2 else ""
            more = f" ({len(found) - 1} more such at line{plural} {lines})"
        yield self.report(
            ctx, node, f"{what} {verb} on {every}: {reads.format(inputs)}{more}; {fix} {where}"
        )

    def _pointless(
        self,
        ctx: LintContext,
        prog: Program,
        flow: Flow,
        loop: Tree,
        declared: set[str],
        trips: int,
        moving: set[str],
    ) -> Finding | None:
        """A counted loop whose body never reads its counter nor anything the passes change
        (besides accumulating into its results): every pass computes the same values."""
        if loop.data != "for_statement":
            return None
        _, cond, update, body = for_parts(loop)
        if update is None:
            return None
        if not isinstance(cond, Tree) or not isinstance(body, Tree) or body.meta.empty:
            return None
        head = flow.within(cond.meta.start_pos, body.meta.start_pos)
        counters = {w.target for w in head if w.target[0] != "#"}
        carried = {w.target for w in flow.within(body.meta.start_pos, loop.meta.end_pos)
                   if w.target[0] != "#" and w.target not in declared}  # fmt: skip
        if not counters or carried & counters:
            return None
        reads = _reads_outside_accumulators(prog, body, carried)
        if reads is None or reads & (carried | counters):
            return None
        # the first work of the body: an invariant expression with a call
        pieces = _pieces(prog, flow, [body], moving, sticky=False)
        if not pieces:
            return None
        first = pieces[0]
        self._mark(loop)
        counter = ", ".join(sorted(counters))
        return self.report(
            ctx,
            first,
            f"the loop at line {ctx.span(loop)[0]} never uses {counter} and its body reads nothing "
            f"that changes between passes: each of its {trips} passes computes the same "
            f"`{short_text(ctx, first, 50)}` (and the rest of the body), so the loop does one "
            f"pass's work {trips} times; make the body depend on {counter} (as probably "
            "intended) or drop the loop",
        )

    # --- a function that runs many times per pixel ------------------------------------------

    def _function(
        self,
        ctx: LintContext,
        prog: Program,
        fn: Function,
        flow: Flow,
        sites: dict[str, _Site],
        fixed: set[str],
        up: dict[int, Tree],
    ) -> Iterator[Finding]:
        params, outside = self._moving_params(ctx, prog, fn, sites, up)
        seed = params | (prog.globals - fixed) | {IMPURE}
        moving = varying(seed, flow.writes)
        runs = sites[_key(fn)].runs
        hot = _loop_of_chain(sites, _key(fn), up)
        found: list[tuple[Tree, int]] = []
        share = 0
        for node in _pieces(prog, flow, CompoundStatement(fn.body).statements, moving):
            if self._covered(node):
                continue
            cost = prog.cost(node, fn)
            around = _enclosing_trips(ctx, node, fn, up)
            share += around * cost
            found.append((node, (runs * around - outside) * cost))
        if not found or share < SHARE * prog.cost(fn.body, fn):
            return
        hot_line = f"the loop at line {ctx.span(hot)[0]}" if hot is not None else "its caller"
        how_often = f"up to {runs} times" if sites[_key(fn)].stated else "many times"
        yield from self._group(
            ctx,
            found,
            f"every call of {fn.name}, which runs {how_often} per pixel from {hot_line}",
            (
                f"it reads none of {fn.name}'s parameters, only {{}}"
                if params >= set(fn.params)
                else "it reads only {}, which do not change between these calls"
            ),  # fmt: skip
            f"once before {hot_line} (or in mainImage) and pass the result in or keep it in a "
            "global",
        )

    def _moving_params(
        self,
        ctx: LintContext,
        prog: Program,
        fn: Function,
        sites: dict[str, _Site],
        up: dict[int, Tree],
    ) -> tuple[set[str], int]:
        """The parameters of the function that change between its repeated calls, and how many
        times per pixel its repeated calls start anew. A call in a loop passes unchanged values
        where its argument reads nothing the loop changes; a call outside any loop, in a
        function that runs repeatedly, is taken to pass new values each time."""
        moving: set[str] = {p for p in fn.params if "out" in fn.params[p][0]}
        outside = 1
        for caller, call in self._calls.get(_key(fn), ()):
            caller_runs = sites.get(_key(caller), _Site(1, None, None)).runs
            loop = _innermost_loop(call, caller, up)
            if self._covered(call):  # the whole call is reported as the same in its loop
                return set(fn.params), 1
            if loop is None or id(loop) not in self._loops:
                if caller_runs > 1:
                    return set(fn.params), 1
                continue
            changed = self._loops[id(loop)][0]
            args = call_args(call)
            for i, param in enumerate(fn.param_order):
                if i >= len(args) or prog.reads(args[i]) & changed:
                    moving.add(param)
            outside = max(outside, caller_runs * _enclosing_trips(ctx, loop, caller, up))
        return moving, outside


def _loops_left(node: Tree, fn: Function, up: dict[int, Tree]) -> set[int]:
    """The loops around the node (ids) that the node's path leaves right after it, so it runs
    at most once per entry to them, not on every pass: `if (hit) { c = texture(...); return c;
    }` leaves every loop of the function, a statement followed by `break` in the same block its
    innermost loop (a `break` in a switch leaves only the switch)."""
    left: set[int] = set()
    returns = breaks = in_switch = False
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data == "jump_statement" and jump_parts(parent)[0] == "return":
            returns = True
        elif parent.data == "switch_statement":
            in_switch = True
        elif parent.data == "compound_statement":
            statements = CompoundStatement(parent).statements
            at = next(i for i, s in enumerate(statements) if s is current)
            for statement in statements[at + 1 :]:
                if isinstance(statement, Tree) and statement.data == "jump_statement":
                    word = jump_parts(statement)[0]
                    returns |= word == "return"
                    breaks |= word == "break" and not in_switch
        elif parent.data in LOOPS and not (
            parent.data == "for_statement" and ForStatement(parent).init is current
        ):
            if returns or breaks:
                left.add(id(parent))
            breaks = in_switch = False
        current = parent
    return left


def _latch(prog: Program, flows: _Flows, caller: Function, call: Tree) -> frozenset[str]:
    """The names of the caller that the called function changes: the globals it writes and
    what the caller computes from them. A test of them guards an event (`if (iTime > endTime)
    startRound();`, where startRound moves endTime on): once it ran, its own test fails."""
    name = call_name(call)
    written = prog.global_writes(name) if name in prog.defined else frozenset()
    return frozenset(varying(written, flows[id(caller)].writes)) if written else frozenset()


def _repeats(
    ctx: LintContext, node: Tree, fn: Function, up: dict[int, Tree], latch: frozenset[str]
) -> int:
    """How many times the node runs per run of its function, at most: the product of the trip
    counts of the loops around it that it does not leave right after it runs, and that are not
    outside a test the node itself turns off (`latch`)."""
    left = _loops_left(node, fn, up)
    total = 1
    latched = False
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data == "if_statement" and latch and names_in(if_parts(parent)[0]) & latch:
            latched = True
        if (
            parent.data in LOOPS
            and id(parent) not in left
            and not latched
            and not (parent.data == "for_statement" and ForStatement(parent).init is current)
        ):
            total *= trip_count(ctx, parent, fn)
        current = parent
    return total


def _may_stick(prog: Program, fn: Function) -> bool:
    """Whether the function's body has anything `_pieces` reports: a loop, a fetch, or a call
    of a function that fetches or loops (a distance helper has none)."""
    if walk_kind(fn.body, *LOOPS):
        return True
    for call in walk_kind(fn.body, "call"):
        name = call_name(call)
        if is_fetch(name) or (name in prog.defined and prog.function_sticky(name)):  # type: ignore[arg-type]
            return True
    return False


def _fetches(node: Tree) -> bool:
    return any(is_fetch(call_name(s)) for s in walk_kind(node, "call"))


def _inputs(node: Tree) -> str:
    """The names the node reads from outside it, for a message."""
    names = sorted(names_in(node) - declared_in(node))
    if len(names) > 4:
        names = names[:4] + ["..."]
    return ", ".join(names)
