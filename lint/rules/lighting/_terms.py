"""Helpers shared by the lighting (L) and performance (PF) rules: the functions of a file with
their locals, which variables each one modifies, constant folding, and the naming conventions
by which shader code says which vector is the normal, the light, the view or the half vector.

Roles are decided by names because GLSL has no other way of saying what a vec3 means. The
conventions recognised (case-insensitive, whole names, or the last field of `s.N`):

- normal N: n, nor, nrm, norm, normal, and names containing "normal" (pixelNormal, wNormal)
- light L: l, lig, ld, ldir, lightdir, lightvec, tolight, wi, and names containing "lightdir",
  "sundir" or "sun_dir" (kSunDir, SUN_DIR)
- view V: v, vdir, view, viewdir, eye dir names (toeye, eyedir, tocamera, directiontocamera), wo
- half H: h, hal, half, halfdir, halfvec, halfway, and names containing "half"
- precomputed cosines: NdotL, NoL, ndl, nl, dotNL, n_dot_l ... (any two of n/l/v/h joined by
  nothing, "o", "d", "dot" or "_dot_"), with an optional suffix such as "signed" or "clamped".

L·H is the same angle as V·H (H bisects L and V), so both count as the Fresnel cosine.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from lark import Token, Tree

from ...analysis.model import semantic_model
from ...analysis.syntax import call_args, callee_name, is_tree
from ...context import LintContext, Node, walk

# --- tree shapes -----------------------------------------------------------------------------


def call_name(node: Node) -> str | None:
    """The called name of a `call` node (`f(x)` -> "f"), None for anything else."""
    return callee_name(node) if is_tree(node, "call") else None  # type: ignore[arg-type]


def var_name(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data == "variable":
        return str(node.children[0])
    return None


def last_name(node: Node) -> str | None:
    """`x` -> "x", `s.N` -> "N" (the innermost name a reader sees), else None."""
    if isinstance(node, Tree):
        if node.data == "variable":
            return str(node.children[0])
        if node.data == "field":
            return str(node.children[-1])
    return None


def root_var(node: Node) -> str | None:
    """The variable an lvalue writes: `a`, `a.x`, `a[i].y` -> "a"."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = node.children[0]
    return var_name(node)


def is_simple(node: Node) -> bool:
    """An identifier, or fields/swizzles/constant indices of one: no side effects, cheap to
    repeat, and a postfix expression that needs no parentheses."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        if node.data == "index" and not (
            isinstance(node.children[1], Tree) and node.children[1].data == "int_literal"
        ):
            return False
        node = node.children[0]
    return var_name(node) is not None


def binary_op(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data == "binary":
        return str(node.children[1])
    return None


def operands(node: Node, op: str) -> list[Node]:
    """The operands of a chain of one associative operator (`a + b + c` -> [a, b, c])."""
    found: list[Node] = []
    stack = [node]  # iterative: long sums must not exhaust the stack
    while stack:
        item = stack.pop()
        if binary_op(item) == op:
            assert isinstance(item, Tree)
            stack += [item.children[2], item.children[0]]
        else:
            found.append(item)
    return found


def parents(root: Tree) -> dict[int, Tree]:
    """Parent of every subtree and token under `root`, keyed by id()."""
    result: dict[int, Tree] = {}
    for node in walk(root):
        for child in node.children:
            result[id(child)] = node
    return result


def names_in(node: Node) -> set[str]:
    """Every variable name read or written under the node (call heads excluded)."""
    if not isinstance(node, Tree):
        return set()
    heads = {id(s.children[0]) for s in walk(node) if s.data == "call"}
    return {str(s.children[0]) for s in walk(node) if s.data == "variable" and id(s) not in heads}


def calls_in(node: Node) -> list[Tree]:
    return [s for s in walk(node) if s.data == "call"] if isinstance(node, Tree) else []


# --- constants -------------------------------------------------------------------------------


def const_value(node: Node, names: dict[str, float] | None = None) -> float | None:
    """The value of a literal expression (`1.0 / 2.2`, `vec3(0.4545)`, `-2.`), else None;
    `names` gives the values of named constants (`8.0 * PI`)."""
    if not isinstance(node, Tree):
        return None
    if names and node.data == "variable":
        return names.get(str(node.children[0]))
    if node.data in ("float_literal", "int_literal"):
        text = str(node.children[0]).rstrip("fFuU")
        try:
            return float(int(text, 0)) if node.data == "int_literal" else float(text)
        except ValueError:
            return None
    if node.data == "unary":
        inner = const_value(node.children[1], names)
        sign = str(node.children[0])
        if inner is None or sign not in "+-":
            return None
        return -inner if sign == "-" else inner
    if node.data == "constructor":
        args = call_args(node)
        values = [const_value(a, names) for a in args]
        if values and all(v is not None and v == values[0] for v in values):
            return values[0]
        return None
    op = binary_op(node)
    if op in ("+", "-", "*", "/"):
        left = const_value(node.children[0], names)
        right = const_value(node.children[2], names)
        if left is None or right is None:
            return None
        if op == "+":
            return left + right
        if op == "-":
            return left - right
        if op == "*":
            return left * right
        return left / right if right else None
    return None


# --- functions, locals, writes ---------------------------------------------------------------


@dataclass
class Function:
    name: str
    node: Tree  # function_definition
    body: Tree  # compound_statement
    params: dict[str, tuple[str, str]]  # name -> (qualifier, type)
    param_order: list[str]
    locals: dict[str, str] = field(default_factory=dict)  # name -> type
    init: dict[str, Node] = field(default_factory=dict)  # name -> initializer (first decl)
    declared_twice: set[str] = field(default_factory=set)
    written: set[str] = field(default_factory=set)  # assigned after declaration, ++, out args

    def type_of(self, name: str) -> str | None:
        if name in self.locals:
            return self.locals[name]
        if name in self.params:
            return self.params[name][1]
        return None

    def value_of(self, name: str) -> Node | None:
        """The initializer of a local that is never written again (its one value)."""
        if name in self.declared_twice or name in self.written:
            return None
        return self.init.get(name)


def _type_text(node: Node) -> str:
    return " ".join(str(t) for t in _tokens(node))


def _tokens(node: Node) -> list[Token]:
    if isinstance(node, Token):
        return [node]
    out: list[Token] = []
    for child in node.children:
        out += _tokens(child)
    return out


def _prototype(proto: Tree) -> tuple[str, dict[str, tuple[str, str]], list[str]]:
    name = ""
    params: dict[str, tuple[str, str]] = {}
    order: list[str] = []
    for child in proto.children:
        if isinstance(child, Token) and child.type == "IDENTIFIER":
            name = str(child)
        elif isinstance(child, Tree) and child.data == "parameter_list":
            for param in child.children:
                qual, typ, pname = "", "", ""
                for part in param.children:
                    if isinstance(part, Tree) and part.data == "type_qualifier":
                        qual = _type_text(part)
                    elif isinstance(part, Tree) and part.data == "type_specifier":
                        typ = _type_text(part)
                    elif isinstance(part, Token) and part.type == "IDENTIFIER":
                        pname = str(part)
                if pname:
                    params[pname] = (qual, typ)
                    order.append(pname)
    return name, params, order


def functions(ctx: LintContext) -> list[Function]:
    """Every function definition of the file, analysed once per file."""
    cached = ctx.cache.get("lighting.functions")
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    result: list[Function] = []
    if ctx.tree is not None:
        defs = [n for n in ctx.tree.children if isinstance(n, Tree)
                and n.data == "function_definition"]  # fmt: skip
        out_params = {}
        for node in defs:
            name, params, order = _prototype(node.children[0])
            out_params[name] = [i for i, p in enumerate(order) if "out" in params[p][0]]
        for node in defs:
            name, params, order = _prototype(node.children[0])
            fn = Function(name, node, node.children[1], params, order)
            _collect(fn, out_params)
            result.append(fn)
    ctx.cache["lighting.functions"] = result
    return result


def function_map(ctx: LintContext) -> dict[str, Function]:
    return {f.name: f for f in functions(ctx)}


def _collect(fn: Function, out_params: dict[str, list[int]]) -> None:
    for node in walk(fn.body):
        if node.data == "variable_declaration":
            typ = ""
            for child in node.children:
                if isinstance(child, Tree) and child.data == "fully_specified_type":
                    typ = _type_text(child.children[-1])
                elif isinstance(child, Tree) and child.data == "declarator":
                    name = str(child.children[0])
                    if name in fn.locals or name in fn.params:
                        fn.declared_twice.add(name)
                    fn.locals[name] = typ
                    init = child.children[-1]
                    if isinstance(init, Tree) and init.data != "array_specifier":
                        fn.init.setdefault(name, init)
        elif node.data == "condition_declaration":
            fn.declared_twice.add(str(node.children[1]))
        fn.written |= writes_of(node, out_params)


def writes_of(node: Tree, out_params: dict[str, list[int]]) -> set[str]:
    """Variables the node itself writes: assignment targets, ++/--, out/inout arguments."""
    if node.data == "assignment":
        name = root_var(node.children[0])
        return {name} if name else set()
    if node.data == "prefix":
        name = root_var(node.children[1])
        return {name} if name else set()
    if node.data == "postfix":
        name = root_var(node.children[0])
        return {name} if name else set()
    if node.data == "call":
        callee = call_name(node)
        if callee in out_params:
            args = call_args(node)
            return {n for i in out_params[callee] if i < len(args) and (n := root_var(args[i]))}
    return set()


def out_param_map(ctx: LintContext) -> dict[str, list[int]]:
    return {f.name: [i for i, p in enumerate(f.param_order) if "out" in f.params[p][0]]
            for f in functions(ctx)}  # fmt: skip


def resolve(node: Node, fn: Function | None, depth: int = 4) -> Node:
    """Follow a local that has one value to that value (a few steps at most)."""
    while depth > 0 and fn is not None:
        name = var_name(node)
        value = fn.value_of(name) if name else None
        if value is None:
            break
        node, depth = value, depth - 1
    return node


# --- roles of vectors and cosines ------------------------------------------------------------

_ROLE_EXACT = {
    "N": {"n", "nor", "nrm", "norm", "normal", "nn", "wn", "sn"},
    "L": {
        "l",
        "lig",
        "ld",
        "ldir",
        "lightdir",
        "lightvec",
        "tolight",
        "wi",
        "lightdirection",
        "lig2",
        "light",
    },
    "V": {
        "v",
        "vdir",
        "view",
        "viewdir",
        "viewvec",
        "toeye",
        "eyedir",
        "tocamera",
        "tocam",
        "directiontocamera",
        "viewdirection",
        "wo",
    },
    "H": {"h", "hal", "half", "halfdir", "halfvec", "halfway", "halfwayvector", "hv"},
}
_ROLE_CONTAINS = {
    "N": ("normal",),
    "L": ("lightdir", "sundir", "sun_dir", "lightvec", "tolight", "light_dir"),
    "V": ("viewdir", "view_dir", "tocamera", "toeye"),
    "H": ("half",),
}
_COSINE = re.compile(
    r"^(?:dot_?|cos_?)?([nlvh])_?(?:dot|o|d)?_?([nlvh])(?:_?(?:signed|clamped|sat|raw|c))?$"
)


def name_role(name: str) -> str | None:
    low = name.lower()
    for role, names in _ROLE_EXACT.items():
        if low in names:
            return role
    for role, parts in _ROLE_CONTAINS.items():
        if any(p in low for p in parts):
            return role
    return None


def vector_role(node: Node, fn: Function | None) -> str | None:
    """N, L, V or H for an expression that names one of those vectors, else None."""
    if isinstance(node, Tree) and node.data == "unary" and str(node.children[0]) in "+-":
        return vector_role(node.children[1], fn)
    if isinstance(node, Tree) and call_name(node) == "normalize":
        args = call_args(node)
        return vector_role(args[0], fn) if len(args) == 1 else None
    name = last_name(node)
    if name is None:
        return None
    role = name_role(name)
    if role is None and var_name(node) is not None:
        value = resolve(node, fn, 1)
        if value is not node:
            return vector_role(value, fn)
    return role


def pair(a: str, b: str) -> str | None:
    """The cosine of two roles: NL, NV, NH, VH (also for L·H), LV."""
    key = "".join(sorted(a + b))
    return {"LN": "NL", "NV": "NV", "HN": "NH", "HV": "VH", "HL": "VH", "LV": "LV"}.get(key)


_PASS_THROUGH = {"max", "clamp", "saturate", "abs", "min"}


def cosine_of(node: Node, fn: Function | None, depth: int = 4) -> str | None:
    """Which cosine an expression is (NL, NV, NH, VH, LV), through clamps and locals."""
    if depth <= 0 or not isinstance(node, Tree):
        return None
    name = call_name(node)
    if name == "dot":
        args = call_args(node)
        if len(args) == 2:
            a, b = vector_role(args[0], fn), vector_role(args[1], fn)
            return pair(a, b) if a and b else None
        return None
    if name in _PASS_THROUGH:
        found = {c for a in call_args(node) if const_value(a) is None
                 and (c := cosine_of(a, fn, depth - 1))}  # fmt: skip
        return found.pop() if len(found) == 1 else None
    leaf = last_name(node)
    if leaf is not None:
        match = _COSINE.match(leaf.lower())
        if match:
            return pair(match.group(1).upper(), match.group(2).upper())
        if var_name(node) is not None and fn is not None:
            value = fn.value_of(leaf)
            if value is not None:
                return cosine_of(value, fn, depth - 1)
    return None


def mentions_normal(ctx: LintContext) -> bool:
    """Whether the file lights a surface: a dot product with a normal anywhere."""
    for fn in functions(ctx):
        for node in calls_in(fn.body):
            if call_name(node) == "dot" and any(vector_role(a, fn) == "N" for a in call_args(node)):
                return True
    return False


# --- terms -----------------------------------------------------------------------------------

FRESNEL_NAME = re.compile(r"fresnel|schlick", re.IGNORECASE)
# Schlick's phase function and Schlick's G1 share the name but are not Fresnel terms.
NOT_FRESNEL_NAME = re.compile(r"phase|ggx|smith|g1|geometry|visib|mask", re.IGNORECASE)


def is_fresnel_name(name: str | None) -> bool:
    return (
        bool(name)
        and bool(FRESNEL_NAME.search(name or ""))
        and not NOT_FRESNEL_NAME.search(name or "")
    )


def schlick_base(node: Node) -> Node | None:
    """For `pow(1 - x, 5.0)` (also clamped or maxed: `pow(clamp(1.0 - x, 0., 1.), 5.)`) the x,
    else None: the cosine of an inline Schlick Fresnel."""
    if call_name(node) != "pow":
        return None
    args = call_args(node)  # type: ignore[arg-type]
    if len(args) != 2 or const_value(args[1]) != 5.0:
        return None
    base = args[0]
    while call_name(base) in ("clamp", "max", "saturate"):
        inner = [a for a in call_args(base) if const_value(a) is None]  # type: ignore[arg-type]
        if len(inner) != 1:
            return None
        base = inner[0]
    if binary_op(base) == "-" and const_value(base.children[0]) == 1.0:  # type: ignore[union-attr]
        return base.children[2]  # type: ignore[union-attr]
    return None


# --- the shared semantic model (lint/analysis/model.py) ---------------------------------------


def is_unit(ctx: LintContext, expr: Node) -> bool:
    """Whether the model proves the expression unit length."""
    return semantic_model(ctx).is_unit(expr)


def may_be_negative(ctx: LintContext, expr: Node) -> bool:
    """Whether the model's range of the value reaches below zero."""
    return semantic_model(ctx).range_of(expr).may_be_negative


def global_constants(ctx: LintContext) -> dict[str, float]:
    """Values of scalar `const` globals with literal initializers (`const float PI = ...`)."""
    cached = ctx.cache.get("lighting.constants")
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    values: dict[str, float] = {}
    for name, init in global_const_inits(ctx).items():  # in order: later ones use earlier
        value = const_value(init, values)
        if value is not None:
            values[name] = value
    ctx.cache["lighting.constants"] = values
    return values


# --- what reaches the output: liveness of values ---------------------------------------------

_CONDITIONS = {"if_statement", "while_statement", "do_statement", "switch_statement"}


def live_names(ctx: LintContext, fn: Function) -> set[str]:
    """Variables of the function whose values can reach its results: what it returns, writes to
    an out parameter or a global, passes to a call for its side effects, or tests in a branch or
    loop condition, and (transitively) every variable those are computed from. A variable that
    is assigned but never reaches one of those is dead: its value is never seen."""
    key = f"lighting.live.{fn.name}.{id(fn.node)}"
    cached = ctx.cache.get(key)
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    outs = out_param_map(ctx)
    local = {n for n in fn.locals} | {p for p, (q, _) in fn.params.items() if "out" not in q}
    deps: dict[str, set[str]] = {}
    seeds: set[str] = set()

    def depend(target: str | None, reads: set[str]) -> None:
        if target is None:
            return
        if target in local:
            deps.setdefault(target, set()).update(reads)
        else:  # an out parameter or a global: the value leaves the function
            seeds.update(reads)

    for node in walk(fn.body):
        if node.data == "jump_statement" and len(node.children) == 2:
            seeds |= names_in(node.children[1])
        elif node.data in _CONDITIONS:
            cond = node.children[1] if node.data == "do_statement" else node.children[0]
            seeds |= names_in(cond)
        elif node.data == "for_statement" and len(node.children) > 2:
            seeds |= names_in(node.children[1])
        elif node.data == "ternary":
            seeds |= names_in(node.children[0])
        elif node.data == "declarator" and len(node.children) > 1:
            depend(str(node.children[0]), names_in(node.children[-1]))
        elif node.data == "assignment":
            target = root_var(node.children[0])
            reads = names_in(node.children[2]) | (names_in(node.children[0]) - {target})
            depend(target, reads)
        elif node.data == "call":
            callee = call_name(node)
            args = call_args(node)
            if callee in outs and outs[callee]:
                reads = set().union(*(names_in(a) for a in args)) if args else set()
                for i in outs[callee]:
                    if i < len(args):
                        depend(root_var(args[i]), reads)
    live = set(seeds)
    todo = list(seeds)
    while todo:
        for name in deps.get(todo.pop(), ()):
            if name not in live:
                live.add(name)
                todo.append(name)
    ctx.cache[key] = live
    return live


def reaches_output(ctx: LintContext, node: Node, fn: Function, up: dict[int, Tree]) -> bool:
    """Whether the value of an expression can be seen outside its function (see live_names):
    it is returned, tested, or stored in a variable whose value is. Conservative: anything the
    walk does not understand counts as reaching."""
    live = live_names(ctx, fn)
    current: Node = node
    while (parent := up.get(id(current))) is not None:
        if parent.data == "declarator":
            return str(parent.children[0]) in live
        if parent.data == "assignment":
            if current is parent.children[0]:
                return True
            target = root_var(parent.children[0])
            local = target in fn.locals or (
                target in fn.params and "out" not in fn.params[target][0]
            )
            return not local or target in live
        if parent.data == "expression_statement":
            return any(s.data == "call" and call_name(s) not in _BUILTIN_PURE
                       for s in walk(parent))  # fmt: skip
        if parent.data in ("jump_statement", "compound_statement", "function_definition"):
            return True
        if parent.data in _CONDITIONS or parent.data == "for_statement":
            return True
        current = parent
    return True


_BUILTIN_PURE = {"dot", "max", "min", "clamp", "pow", "normalize", "length", "mix", "abs"}


def callable_from_main(ctx: LintContext) -> set[str] | None:
    """Names of the functions mainImage calls, directly or through others (None without one)."""
    defined = function_map(ctx)
    if "mainImage" not in defined:
        return None
    seen = {"mainImage"}
    todo = ["mainImage"]
    while todo:
        fn = defined[todo.pop()]
        for call in calls_in(fn.body):
            name = call_name(call)
            if name in defined and name not in seen:
                seen.add(name)
                todo.append(name)
    return seen


def _vec3_or_unknown(ctx: LintContext, node: Node) -> bool:
    typ = semantic_model(ctx).type_of(node)
    return typ is None or typ == "vec3"


def lighting_cosines(ctx: LintContext) -> list[tuple[Tree, Function]]:
    """The dot products that light a 3D surface: dot(N, L), dot(N, V) or dot(N, H) of two vec3
    (not a 2D vector that happens to be called n, nor a hash's argument dotted with constants),
    in a function that mainImage runs, whose value reaches that function's result (not a
    lighting term computed and then never used)."""
    cached = ctx.cache.get("lighting.cosines")
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    result: list[tuple[Tree, Function]] = []
    used = callable_from_main(ctx)
    up = parents(ctx.tree) if ctx.tree is not None else {}
    for fn in functions(ctx):
        if used is not None and fn.name not in used:
            continue
        for node in calls_in(fn.body):
            if call_name(node) != "dot" or not _lighting_dot(node, fn):
                continue
            if not all(_vec3_or_unknown(ctx, a) for a in call_args(node)):
                continue
            if reaches_output(ctx, node, fn, up):
                result.append((node, fn))
    ctx.cache["lighting.cosines"] = result
    return result


_LIGHT_WORD = re.compile(r"light|lig|sun", re.I)


def _light_like(node: Node, fn: Function) -> bool:
    """A light (or view, half) vector by its role, or named after a light: `vLight`, `ligt`,
    `sun.dir`, `l.dir` with l the light (a field of a light-named variable)."""
    if vector_role(node, fn) in ("L", "V", "H"):
        return True
    base: Node = node
    while isinstance(base, Tree) and (base.data in ("field", "index") or call_name(base) ==
                                      "normalize" or base.data == "unary"):  # fmt: skip
        base = (
            call_args(base)[0]
            if call_name(base) == "normalize"
            else (base.children[1] if base.data == "unary" else base.children[0])
        )
    name = var_name(base)
    if name is None:
        return False
    return name_role(name) == "L" or bool(_LIGHT_WORD.search(name))


def _lighting_dot(node: Tree, fn: Function) -> bool:
    """dot(N, X) with X a light, view or half vector (see _light_like)."""
    if cosine_of(node, fn) in ("NL", "NV", "NH"):
        return True
    args = call_args(node)
    if len(args) != 2:
        return False
    roles = [vector_role(a, fn) for a in args]
    return any(r == "N" and _light_like(args[1 - i], fn) for i, r in enumerate(roles))


def lights_surface(ctx: LintContext) -> bool:
    """Whether the shader lights a 3D surface (see lighting_cosines)."""
    return bool(lighting_cosines(ctx))


# --- compile-time constants ------------------------------------------------------------------

_FOLDABLE_CALLS = {
    "normalize",
    "length",
    "sqrt",
    "inversesqrt",
    "pow",
    "exp",
    "exp2",
    "log",
    "log2",
    "sin",
    "cos",
    "tan",
    "radians",
    "degrees",
    "abs",
    "min",
    "max",
    "clamp",
    "mix",
    "dot",
    "cross",
    "floor",
    "fract",
    "mod",
    "sign",
    "step",
    "smoothstep",
}


def global_const_inits(ctx: LintContext) -> dict[str, Node]:
    """The initializers of `const` globals, by name."""
    cached = ctx.cache.get("lighting.const_inits")
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    values: dict[str, Node] = {}
    for node in ctx.tree.children if ctx.tree is not None else ():
        if not (isinstance(node, Tree) and node.data == "variable_declaration"):
            continue
        spec = node.children[0]
        qual = spec.children[0] if isinstance(spec, Tree) and spec.children else None
        if not (isinstance(qual, Tree) and qual.data == "type_qualifier"
                and "const" in [str(t) for t in qual.children]):  # fmt: skip
            continue
        for child in node.children[1:]:
            if isinstance(child, Tree) and child.data == "declarator" and len(child.children) > 1:
                init = child.children[-1]
                if isinstance(init, Tree) and init.data != "array_specifier":
                    values[str(child.children[0])] = init
    ctx.cache["lighting.const_inits"] = values
    return values


def is_compile_time(ctx: LintContext, node: Node, fn: Function | None, depth: int = 6) -> bool:
    """Whether every value the expression can take is known when the shader is compiled: it is
    built only from literals (macros are expanded already), `const` names, locals whose one
    value is such an expression, and builtin calls of those. The compiler folds it: no
    instruction runs for it."""
    if depth <= 0 or not isinstance(node, Tree):
        return False
    if node.data in ("float_literal", "int_literal", "bool_literal"):
        return True
    if node.data == "variable":
        name = str(node.children[0])
        if fn is not None and (name in fn.locals or name in fn.params):
            value = fn.value_of(name) if name not in fn.params else None
            return value is not None and is_compile_time(ctx, value, fn, depth - 1)
        init = global_const_inits(ctx).get(name)
        return init is not None and is_compile_time(ctx, init, None, depth - 1)
    if node.data == "constructor":
        return all(is_compile_time(ctx, a, fn, depth - 1) for a in call_args(node))
    if node.data == "call":
        return call_name(node) in _FOLDABLE_CALLS and all(
            is_compile_time(ctx, a, fn, depth - 1) for a in call_args(node)
        )
    if node.data in ("binary", "unary", "field", "ternary"):
        kids = [c for c in node.children if isinstance(c, Tree)]
        if node.data == "field":
            kids = kids[:1]
        return bool(kids) and all(is_compile_time(ctx, k, fn, depth - 1) for k in kids)
    return False


def known_value(ctx: LintContext, node: Node) -> bool:
    """Whether the model knows the value exactly where it is read (every component a single
    number): a variable that still holds the constant it was given, as in `vec3 L =
    vec3(7.4, 5.6, 4.4); L = pow(L, vec3(5.0));`. Constant propagation folds what reads it."""
    value = semantic_model(ctx).value_of(node)
    parts = value.comps if value.comps is not None else (value.range,)
    return all(p.lo == p.hi for p in parts)


def folded(ctx: LintContext, node: Node, fn: Function | None) -> bool:
    """A compile-time constant (is_compile_time) or a value the model knows exactly."""
    return is_compile_time(ctx, node, fn) or known_value(ctx, node)
