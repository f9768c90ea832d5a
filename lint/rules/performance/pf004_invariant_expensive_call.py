"""PF004 invariant-expensive-call-in-loop."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from lark import Tree

from ...analysis.functions import Function, functions
from ...analysis.invariance import (
    IMPURE,
    LOOPS,
    Program,
    declared_in,
    region_parts,
    varying,
    writes_in,
)
from ...analysis.syntax import call_args, call_name, names_in, root_var
from ...context import LintContext, Node, walk, walk_kind
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


@dataclass
class _Site:
    runs: int  # how many times the function runs per pixel, at most
    caller: str | None  # the caller that makes it run that often
    call: Tree | None  # the call in that caller
    stated: bool = True  # every loop on the way states its trip count (no march)


def _runs(ctx: LintContext, up: dict[int, Tree]) -> dict[str, _Site]:
    """How many times each function runs per pixel, at most (mainImage once, another function
    the largest over its call sites of the caller's runs times the loops around the call), with
    the call site that gives that count."""
    defined = {f.name: f for f in functions(ctx)}
    sites: dict[str, list[tuple[Function, Tree]]] = {}
    for fn in defined.values():
        for node in walk_kind(fn.body, "call"):
            if (name := call_name(node)) in defined and name != fn.name:
                sites.setdefault(name or "", []).append((fn, node))
    result: dict[str, _Site] = {}

    def count(name: str, depth: int) -> int:
        if name in result:
            return result[name].runs
        result[name] = _Site(1, None, None)  # a guard against call cycles
        if name == "mainImage" or depth > 16:
            return 1
        best = _Site(1, None, None)
        for caller, call in sites.get(name, ()):
            runs = count(caller.name, depth + 1) * _enclosing_trips(ctx, call, caller, up)
            if runs > best.runs:
                stated = result[caller.name].stated and _stated(ctx, call, caller, up)
                best = _Site(min(runs, 1 << 30), caller.name, call, stated)
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
                parent.data == "for_statement" and parent.children[0] is node
            ):
                return parent
            node = parent
        name = site.caller
    return None


def _fixed_globals(ctx: LintContext, prog: Program, sites: dict[str, _Site]) -> set[str]:
    """Globals that keep their value while any function runs repeatedly: written only by
    functions that run once per pixel, and there outside loops (`time = iTime * 0.5;` at the top
    of mainImage)."""
    moving: set[str] = set()
    for fn in functions(ctx):
        once = sites.get(fn.name, _Site(1, None, None)).runs <= 1
        for loop in walk_kind(fn.body, *LOOPS) if once else [fn.body]:
            moving |= {w.target for w in writes_in(prog, loop)}
    return prog.globals - moving


def _moving_in_loop(
    prog: Program, fn: Function, loop: Tree, decls: list[tuple[str, int]]
) -> tuple[set[str], set[str]]:
    """The names that vary between the passes of the loop, and the names declared in it (fresh
    on every pass)."""
    parts = region_parts(loop)
    writes = [w for part in parts for w in writes_in(prog, part)]
    # a name declared in the loop that also names a variable outside it (a shadowed counter, a
    # parameter, a global) is taken as the outer one: varying if written
    declared = set().union(*(declared_in(p) for p in parts))
    declared -= set(fn.params) | prog.globals | _declared_outside(decls, loop)
    seed = {w.target for w in writes if w.target not in declared} | {IMPURE}
    for part in parts:
        for call in walk(part):
            if call.data == "call" and (name := call_name(call)) in prog.defined:
                seed |= prog.global_writes(name)  # type: ignore[arg-type]
    return varying(seed, writes), declared


def fns_of(prog: Program) -> list[Function]:
    return [fn for group in prog.defined.values() for fn in group]


def _innermost_loop(node: Tree, fn: Function, up: dict[int, Tree]) -> Tree | None:
    """The innermost loop of the function around the node (a for-init is not in its loop)."""
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data in LOOPS and not (
            parent.data == "for_statement" and parent.children[0] is current
        ):
            return parent
        current = parent
    return None


def _declared_outside(decls: list[tuple[str, int]], loop: Tree) -> set[str]:
    """Names declared in the function but outside the loop's repeated parts (for-init
    included): `decls` holds each declaration's name and offset."""
    first = region_parts(loop)[0]
    start = first.meta.start_pos if isinstance(first, Tree) else loop.meta.start_pos
    return {name for name, at in decls if not start <= at < loop.meta.end_pos}


def _reads_outside_accumulators(prog: Program, body: Node, carried: set[str]) -> set[str] | None:
    """The names the loop body reads, leaving out each carried variable's own operand in its
    update (`d = min(d, E)`, `s += E`, `x = E`, `n++`); None when a carried variable is updated
    some other way or a call writes globals."""
    found: set[str] = set()
    stack: list[Node] = [body]
    while stack:
        node = stack.pop()
        if not isinstance(node, Tree):
            continue
        if node.data == "variable":
            found.add(str(node.children[0]))
            continue
        if node.data == "call" and (name := call_name(node)) in prog.defined:
            if prog.global_writes(name):  # type: ignore[arg-type]
                return None
            found |= prog.global_reads(name)  # type: ignore[arg-type]
        if node.data in ("prefix", "postfix"):
            operand = node.children[1] if node.data == "prefix" else node.children[0]
            if root_var(operand) in carried:
                continue
        if node.data == "assignment" and (target := root_var(node.children[0])) in carried:
            lhs, op, rhs = node.children
            found |= names_in(lhs) - {target}
            if op == "=" and call_name(rhs) in ("min", "max"):
                args = call_args(rhs)  # type: ignore[arg-type]
                rest = [a for a in args if not (isinstance(a, Tree) and a.data == "variable"
                                                and str(a.children[0]) == target)]  # fmt: skip
                stack += rest if len(rest) == len(args) - 1 else args
            else:
                stack.append(rhs)
            continue
        stack += node.children
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
    default = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        constants, other_globals = _global_names(ctx)
        fns = functions(ctx)
        overloads: dict[str, list[Function]] = {}
        for f in fns:
            overloads.setdefault(f.name, []).append(f)
        prog = Program(
            ctx,
            overloads,
            other_globals,
            lambda loop, fn: trip_count(ctx, loop, fn),
        )
        up = ctx.parents()
        sites = _runs(ctx, up)
        fixed = _fixed_globals(ctx, prog, sites)
        self._reported: list[tuple[int, int]] = []
        # what varies in every loop first: the calls in a loop tell which parameters of the
        # called function change between its calls there
        self._loops: dict[int, tuple[set[str], set[str]]] = {}
        for fn in fns:
            decls = [(str(n.children[0]), n.meta.start_pos)
                     for n in walk_kind(fn.body, "declarator")]  # fmt: skip
            for loop in walk_kind(fn.body, *LOOPS):
                self._loops[id(loop)] = _moving_in_loop(prog, fn, loop, decls)
        for fn in fns:
            runs = sites.get(fn.name, _Site(1, None, None)).runs
            for loop in walk_kind(fn.body, *LOOPS):
                if not self._covered(loop):
                    yield from self._loop(ctx, prog, fn, loop, runs, up)
        for fn in fns:
            if sites.get(fn.name, _Site(1, None, None)).runs >= 2:
                yield from self._function(ctx, prog, fn, sites, fixed, up)

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
        loop: Tree,
        runs: int,
        up: dict[int, Tree],
    ) -> Iterator[Finding]:
        trips = trip_count(ctx, loop, fn)
        if trips < 2:
            return
        parts = region_parts(loop)
        moving, declared = self._loops[id(loop)]
        line = ctx.span(loop)[0]
        outside = runs * _enclosing_trips(ctx, loop, fn, up)
        pointless = self._pointless(ctx, prog, loop, declared, trips, moving)
        if pointless is not None:
            yield pointless
            return
        found: list[tuple[Tree, int]] = []
        share: list[int] = []
        for node in self._candidates(prog, parts, moving):
            if self._covered(node):
                continue
            inside = runs * _enclosing_trips(ctx, node, fn, up)
            found.append((node, (inside - outside) * prog.cost(node, fn)))
            share.append(inside // max(1, outside) * prog.cost(node, fn))
        if sum(share) < SHARE * prog.cost(loop, fn):
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
        loop: Tree,
        declared: set[str],
        trips: int,
        moving: set[str],
    ) -> Finding | None:
        """A counted loop whose body never reads its counter nor anything the passes change
        (besides accumulating into its results): every pass computes the same values."""
        if loop.data != "for_statement" or len(loop.children) < 4:
            return None
        cond, step, body = loop.children[1], loop.children[2], loop.children[3]
        counters = {w.target for part in (cond, step) for w in writes_in(prog, part)}
        body_writes = writes_in(prog, body)
        carried = {w.target for w in body_writes if w.target not in declared}
        if not counters or carried & counters:
            return None
        reads = _reads_outside_accumulators(prog, body, carried)
        if reads is None or reads & (carried | counters):
            return None
        # the first work of the body: an invariant expression with a call
        first = next((n for n in self._candidates(prog, [body], moving, sticky=False)
                      if any(s.data == "call" for s in walk(n))), None)  # fmt: skip
        if first is None:
            return None
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
        sites: dict[str, _Site],
        fixed: set[str],
        up: dict[int, Tree],
    ) -> Iterator[Finding]:
        params, outside = self._moving_params(ctx, prog, fn, sites, up)
        writes = writes_in(prog, fn.body)
        seed = params | (prog.globals - fixed) | {IMPURE}
        moving = varying(seed, writes)
        runs = sites[fn.name].runs
        hot = _loop_of_chain(sites, fn.name, up)
        found: list[tuple[Tree, int]] = []
        share: list[int] = []
        for node in self._candidates(prog, list(fn.body.children), moving):
            if self._covered(node):
                continue
            share.append(_enclosing_trips(ctx, node, fn, up) * prog.cost(node, fn))
            found.append((node, (runs * _enclosing_trips(ctx, node, fn, up) - outside)
                          * prog.cost(node, fn)))  # fmt: skip
        hot_line = f"the loop at line {ctx.span(hot)[0]}" if hot is not None else "its caller"
        if sum(share) < SHARE * prog.cost(fn.body, fn):
            return
        yield from self._group(
            ctx,
            found,
            f"every call of {fn.name}, which runs "
            + (f"up to {runs} times per pixel" if sites[fn.name].stated else "many times per pixel")
            + f" from {hot_line}",
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
        for caller in fns_of(prog):
            if caller.name == fn.name:
                continue
            caller_runs = sites.get(caller.name, _Site(1, None, None)).runs
            for call in walk_kind(caller.body, "call"):
                if call_name(call) != fn.name:
                    continue
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

    # --- candidates -------------------------------------------------------------------------

    def _candidates(
        self, prog: Program, nodes: list[Node], moving: set[str], sticky: bool = True
    ) -> Iterator[Tree]:
        """The largest expressions (and inner loops) under the nodes that read nothing that
        varies and, with `sticky`, fetch or loop; in source order."""
        stack: list[tuple[Node, frozenset[str]]] = [(n, frozenset()) for n in reversed(nodes)]
        while stack:
            node, extra = stack.pop()
            if not isinstance(node, Tree):
                continue
            kind = node.data
            if kind in LOOPS:
                if sticky and _unchanged(prog, node, moving | extra) and not _exits(node):
                    yield node
                    continue
                written = extra | {w.target for w in writes_in(prog, node)}
                parts = list(node.children)
                if kind == "for_statement":
                    stack += [(c, written) for c in reversed(parts[1:])]
                    stack.append((parts[0], extra))
                else:
                    stack += [(c, written) for c in reversed(parts)]
                continue
            if kind == "assignment":
                stack.append((node.children[2], extra))
                continue
            if kind in _EXPRESSIONS and _unchanged(prog, node, moving | extra):
                if not _has_side_effects(node) and (prog.sticky(node) if sticky
                                                    else _does_work(node)):  # fmt: skip
                    yield node
                continue
            stack += [(c, extra) for c in reversed(node.children)]


def _unchanged(prog: Program, node: Node, moving: set[str]) -> bool:
    names = prog.reads(node)
    return not (names & moving)


def _has_side_effects(node: Tree) -> bool:
    return any(s.data in ("assignment", "prefix", "postfix") for s in walk(node))


def _does_work(node: Tree) -> bool:
    return any(s.data == "call" for s in walk(node))


def _exits(loop: Tree) -> bool:
    """A return or discard in the loop: it cannot be moved as a whole."""
    return any(
        s.data == "jump_statement" and str(s.children[0]) in ("return", "discard")
        for s in walk(loop)
    )


def _fetches(node: Tree) -> bool:
    from ...analysis.invariance import is_fetch

    return any(s.data == "call" and is_fetch(call_name(s)) for s in walk(node))


def _inputs(node: Tree) -> str:
    """The names the node reads from outside it, for a message."""
    names = sorted(names_in(node) - declared_in(node))
    if len(names) > 4:
        names = names[:4] + ["..."]
    return ", ".join(names)
