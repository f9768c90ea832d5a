"""Portability (P): what GLSL ES 3.00 and ShaderToy reject although desktop drivers or older
ShaderToy accepted it: the mainImage entry point, ES 1.00 names, implicit int-to-float
conversion, non-constant global initialisers, reserved words."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Token, Tree

from glint.compiler.glsl.keywords import RESERVED_WORDS, words
from glint.compiler.glsl.pptokens import tokenize
from glint.compiler.shadertoy import UNIFORM_NAMES, is_complete

from ..analysis.flow import parameter_parts, prototype_parts, type_of_declaration
from ..analysis.model import Model, semantic_model
from ..analysis.types import is_float_like
from ..context import LintContext, Node, walk
from ..finding import Finding, Fix
from . import Rule, register

# --- shared helpers ------------------------------------------------------------------------


def _es1(ctx: LintContext) -> bool:
    """A complete `#version 100` (or desktop 1.x) shader, where the ES 1.00 names are right."""
    version = ctx.pre.version if ctx.pre is not None else None
    return bool(version) and version.split()[0] in ("100", "110", "120")  # type: ignore[union-attr]


def _functions(ctx: LintContext) -> list[Tree]:
    assert ctx.tree is not None
    return [n for n in ctx.tree.children if isinstance(n, Tree) and n.data == "function_definition"]


def _defined_names(ctx: LintContext) -> set[str]:
    """Every function and global variable the file defines."""
    names: set[str] = set()
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not isinstance(node, Tree):
            continue
        proto = node.children[0] if node.data == "function_definition" else node
        if isinstance(proto, Tree) and proto.data == "function_prototype":
            names.add(str(proto.children[1]))
        if node.data == "variable_declaration":
            names.update(str(d.children[0]) for d in node.children[1:] if isinstance(d, Tree))
    return names


def _declares(node: Tree, name: str) -> bool:
    """Whether a local of that name is declared anywhere under the node."""
    return any(
        sub.data in ("declarator", "condition_declaration")
        and any(isinstance(c, Token) and c == name for c in sub.children)
        for sub in walk(node)
    )


def _main_image_out(ctx: LintContext) -> tuple[Tree, str] | None:
    """mainImage's definition and the name of its `out vec4` colour, when its signature is
    the one ShaderToy calls."""
    for fdef in _functions(ctx):
        ret, name, params = prototype_parts(fdef.children[0])  # type: ignore[arg-type]
        if name == "mainImage" and _signature_problem(ret, params) is None:
            pname = parameter_parts(params[0])[3]
            if pname is not None:
                return fdef, str(pname)
    return None


def _signature_problem(ret: str, params: list[Tree]) -> str | None:
    """What is wrong with a mainImage signature; None when ShaderToy can call it."""
    parts = [parameter_parts(p) for p in params]
    if len(parts) != 2:
        return f"it takes {len(parts)} parameter{'s' if len(parts) != 1 else ''}, not 2"
    (q0, t0, a0, _), (q1, t1, a1, _) = parts
    if t0 != "vec4" or a0 or q0 not in ("out", "inout"):
        return "its first parameter must be `out vec4` (the pixel's colour)"
    if t1 != "vec2" or a1 or q1 != "in":
        return "its second parameter must be `in vec2` (the pixel's coordinates)"
    if ret != "void":
        return "it must return void"
    return None


def _prototypes(tree: Tree) -> list[Tree]:
    """The prototypes of every function the file defines or declares."""
    found = []
    for node in tree.children:
        if isinstance(node, Tree) and node.data == "function_definition":
            node = node.children[0]  # type: ignore[assignment]
        if isinstance(node, Tree) and node.data == "function_prototype":
            found.append(node)
    return found


def _qualifier_words(spec: Tree) -> set[str]:
    """The qualifiers of a `fully_specified_type` (`const`, `uniform`, `highp`, ...)."""
    first = spec.children[0]
    if isinstance(first, Tree) and first.data == "type_qualifier":
        return {str(t) for t in first.children if isinstance(t, Token)}
    return set()


def _parents(tree: Tree) -> dict[int, Tree]:
    """Parent of every subtree and token, by id (lark nodes hash by value, not identity)."""
    parents: dict[int, Tree] = {}
    for node in walk(tree):
        for child in node.children:
            parents[id(child)] = node
    return parents


# --- P001 ----------------------------------------------------------------------------------


@register
class MainImageSignature(Rule):
    """Finds an Image-tab shader whose entry point is not
    `void mainImage(out vec4 fragColor, in vec2 fragCoord)` (names are free, `in` optional):
    a wrong parameter list or return type, or no mainImage in code that writes the pixel
    through `gl_FragColor`/`gl_FragCoord`.

    A file without mainImage that uses neither is taken for library code (a Common tab, a
    file of helpers) and not reported, and one that defines `main` or opens with `#version`
    is a complete shader, which needs no mainImage.

    Why it matters: ShaderToy appends a `main` that calls mainImage with exactly these
    arguments; any other signature fails to compile there with an error in code you did not
    write.

    Example:
        void mainImage(out vec3 color, vec2 uv) { color = vec3(uv, 0.0); }

    Fix:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) { ... }
    """

    code = "P001"
    name = "main-image-signature"
    category = "portability"
    severity = "error"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        protos = _prototypes(ctx.tree)
        names = {str(p.children[1]) for p in protos}
        if "main" in names or is_complete(ctx.text):
            return
        mains = [p for p in protos if p.children[1] == "mainImage"]
        problems = []
        for proto in mains:
            ret, name, params = prototype_parts(proto)
            problem = _signature_problem(ret, params)
            if problem is None:
                if parameter_parts(params[0])[0] == "inout":
                    yield ctx.finding(
                        self.code, "warning", name,
                        "mainImage's colour should be `out vec4`, not `inout`: ShaderToy "
                        "passes no colour in",
                    )  # fmt: skip
                return
            problems.append((name, problem))
        for name, problem in problems[:1]:
            yield self.report(
                ctx, name, f"mainImage has the wrong signature: {problem}; ShaderToy calls "
                "`void mainImage(out vec4 fragColor, in vec2 fragCoord)`",
            )  # fmt: skip
        if mains:
            return
        near = [p.children[1] for p in protos if str(p.children[1]).lower().replace("_", "")
                == "mainimage"]  # fmt: skip
        if near:
            yield self.report(ctx, near[0], f"`{near[0]}` is not `mainImage`: ShaderToy "
                              "calls `mainImage`, with this capitalisation")  # fmt: skip
            return
        uses = next((n for n in ctx.nodes("variable")
                     if n.children[0] in ("gl_FragColor", "gl_FragData", "gl_FragCoord")),
                    None)  # fmt: skip
        if uses is not None:
            yield self.report(
                ctx, uses, "no mainImage: ShaderToy calls `void mainImage(out vec4 fragColor, "
                "in vec2 fragCoord)`; move the pixel code into it",
            )  # fmt: skip


# --- P002 ----------------------------------------------------------------------------------


@register
class FragColor(Rule):
    """Finds `gl_FragColor` and `gl_FragData`, which GLSL ES 3.00 removed.

    Why it matters: ShaderToy compiles GLSL ES 3.00, where these names are undeclared; the
    colour goes out through mainImage's `out vec4` parameter instead.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            gl_FragColor = vec4(1.0);
        }

    Fix:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor = vec4(1.0);
        }
        (`--fix` does this inside mainImage, where the parameter's name is known.)
    """

    code = "P002"
    name = "gl-fragcolor"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if _es1(ctx):
            return
        main = _main_image_out(ctx)
        inside: set[int] = set()
        if main is not None and not _declares(main[0].children[1], main[1]):  # type: ignore[arg-type]
            inside = {id(n) for n in walk(main[0])}
        parents = _parents(ctx.tree)
        for node in ctx.nodes("variable"):
            if node.children[0] not in ("gl_FragColor", "gl_FragData"):
                continue
            target: Node = node
            if node.children[0] == "gl_FragData":
                parent = parents.get(id(node))
                at_zero = (parent is not None and parent.data == "index"
                           and _literal(parent.children[1]) == "0")  # fmt: skip
                target = parent if at_zero else node  # type: ignore[assignment]
            fix = None
            if id(node) in inside and (target is not node or node.children[0] == "gl_FragColor"):
                edit = ctx.replace(target, main[1])  # type: ignore[index]
                fix = Fix(f"write `{main[1]}`", (edit,)) if edit else None  # type: ignore[index]
            old = ctx.node_text(target).strip() or str(node.children[0])
            where = f"`{main[1]}`" if main else "mainImage's `out vec4` parameter"
            message = f"`{old}` does not exist in GLSL ES 3.00; write {where}"
            yield self.report(ctx, target, message, fix)


def _literal(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data in ("int_literal", "float_literal"):
        return str(node.children[0])
    return None


# --- P003 ----------------------------------------------------------------------------------

# GLSL ES 1.00 (and its extensions') texture functions and their ES 3.00 overloads.
ES1_TEXTURE = {
    "texture2D": "texture",
    "textureCube": "texture",
    "texture3D": "texture",
    "texture2DLod": "textureLod",
    "textureCubeLod": "textureLod",
    "texture2DLodEXT": "textureLod",
    "textureCubeLodEXT": "textureLod",
    "texture2DProj": "textureProj",
    "texture2DProjLod": "textureProjLod",
    "texture2DProjLodEXT": "textureProjLod",
    "texture2DGradEXT": "textureGrad",
    "textureCubeGradEXT": "textureGrad",
    "texture2DProjGradEXT": "textureProjGrad",
}


@register
class Es1Texture(Rule):
    """Finds the GLSL ES 1.00 texture functions (`texture2D`, `textureCube`, `texture2DLod`,
    `texture2DProj`, their EXT variants), which GLSL ES 3.00 removed.

    Why it matters: ES 3.00 has one overloaded `texture()` (and `textureLod`, `textureProj`,
    `textureGrad`) for every sampler type; the old names are undeclared and the shader fails
    to compile on ShaderToy and in WebGL 2.

    Example:
        vec4 c = texture2D(iChannel0, uv);

    Fix:
        vec4 c = texture(iChannel0, uv);   (`--fix` renames them)
    """

    code = "P003"
    name = "es1-texture-function"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if _es1(ctx):
            return
        own = _defined_names(ctx)  # a file may define its own texture2D as a shim
        for node in ctx.nodes("call"):
            callee = node.children[0]
            if not (isinstance(callee, Tree) and callee.data == "variable"):
                continue
            old = str(callee.children[0])
            new = ES1_TEXTURE.get(old)
            if new is None or old in own:
                continue
            edit = ctx.replace(callee, new)
            fix = Fix(f"use `{new}`", (edit,)) if edit else None
            message = f"`{old}` is GLSL ES 1.00; GLSL ES 3.00 has `{new}`"
            yield self.report(ctx, callee, message, fix)


# --- P004 ----------------------------------------------------------------------------------


@register
class OldShadertoyUniform(Rule):
    """Finds ShaderToy uniforms under their old names (`iGlobalTime`, renamed `iTime` in
    2017) and `iChannelResolution` used without an index.

    Why it matters: ShaderToy no longer declares `iGlobalTime`, so old shaders pasted in fail
    with "undeclared identifier". `iChannelResolution` is an array of four vec3, one per
    channel; `iChannelResolution.xy` does not compile.

    Example:
        float t = iGlobalTime;
        vec2 size = iChannelResolution.xy;

    Fix:
        float t = iTime;   (`--fix` renames it)
        vec2 size = iChannelResolution[0].xy;
    """

    code = "P004"
    name = "old-shadertoy-uniform"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        own = _defined_names(ctx)
        if "iGlobalTime" in own:
            return  # the file declares it itself
        shadowed = _declares(ctx.tree, "iTime") or "iTime" in own
        for node in walk(ctx.tree):
            if node.data == "variable" and node.children[0] == "iGlobalTime":
                edit = None if shadowed else ctx.replace(node, "iTime")
                fix = Fix("use `iTime`", (edit,)) if edit else None
                message = "`iGlobalTime` is ShaderToy's old name for `iTime`"
                yield self.report(ctx, node, message, fix)
            elif node.data == "field" and "iChannelResolution" not in own:
                base = node.children[0]
                if (
                    isinstance(base, Tree)
                    and base.data == "variable"
                    and (base.children[0] == "iChannelResolution")
                ):
                    message = ("`iChannelResolution` is an array, one vec3 per channel: "
                               "index it, e.g. `iChannelResolution[0].xy`")  # fmt: skip
                    yield self.report(ctx, node, message)


# --- P005 ----------------------------------------------------------------------------------

# Builtins with only float overloads: an int argument never matches (GLSL ES 3.00, section 8).
FLOAT_ONLY = words(
    """radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow exp log
    exp2 log2 sqrt inversesqrt floor trunc round roundEven ceil fract mod mix step smoothstep
    length distance dot cross normalize faceforward reflect refract dFdx dFdy fwidth"""
)
# Builtins with int overloads too: an int literal is wrong only beside a float argument.
INT_OVERLOADS = frozenset({"abs", "sign", "min", "max", "clamp"})
# Texture functions whose argument at this position is a float (bias or level of detail).
FLOAT_ARG_AT = {"texture": 2, "textureProj": 2, "textureLod": 2, "textureProjLod": 2}
_ARITHMETIC = frozenset({"+", "-", "*", "/", "<", ">", "<=", ">=", "==", "!="})
_DECIMAL = re.compile(r"^(0|[1-9][0-9]*)$")


@register
class IntWhereFloat(Rule):
    """Finds an int where a float is needed: `float x = 1;`, `x * 2` or `x > 0` with a float
    `x`, `pow(x, 2)`, `textureLod(s, uv, 0)`, `return 0;` in a float function. Constructors
    convert, so `vec3(1, 0, 0)` is fine.

    Why it matters: GLSL ES has no implicit int-to-float conversion (desktop GL does), so code
    that compiles on a desktop driver fails on ShaderToy, WebGL and phones.

    Example:
        float d = 1;
        col *= pow(d, 2);

    Fix:
        float d = 1.0;
        col *= pow(d, 2.0);
        (`--fix` rewrites int literals; an int variable needs `float(i)`, by hand.)
    """

    code = "P005"
    name = "int-where-float"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        model = semantic_model(ctx)
        types = model.type_of
        parents = _parents(ctx.tree)
        for node in walk(ctx.tree):
            if node.data == "int_literal":
                if str(node.children[0])[-1] in "uU":
                    continue
                expr: Tree = node
                while (parent := parents.get(id(expr))) is not None and parent.data == "unary" \
                        and parent.children[0] in ("-", "+"):  # fmt: skip
                    expr = parent
            elif node.data == "variable" and types(node) == "int":
                expr = node
            else:
                continue
            why = self.float_context(expr, parents, model)
            if why is None:
                continue
            text = str(node.children[0])
            if node.data == "variable":
                message = (f"int `{text}` {why}; GLSL ES has no implicit conversion: "
                           f"write `float({text})`")  # fmt: skip
                yield self.report(ctx, node, message)
                continue
            fix = None
            if _DECIMAL.match(text):
                edit = ctx.replace(node, text + ".0")
                fix = Fix(f"write `{text}.0`", (edit,)) if edit else None
            message = (f"int literal `{text}` {why}; GLSL ES has no implicit conversion: "
                       f"write `{text}.0`")  # fmt: skip
            yield self.report(ctx, node, message, fix)

    def float_context(self, expr: Tree, parents: dict[int, Tree], model: Model) -> str | None:
        """Why the expression must be a float there, or None if it need not (or we cannot
        tell)."""
        types = model.type_of
        while True:
            parent = parents.get(id(expr))
            if parent is None:
                return None
            kids = parent.children
            kind = parent.data
            if kind == "declarator" and expr is kids[-1] and len(kids) > 1:
                decl = parents.get(id(parent))
                if decl is None or decl.data != "variable_declaration":
                    return None
                ty, arr = type_of_declaration(decl.children[0])  # type: ignore[arg-type]
                is_arr = arr or any(isinstance(c, Tree) and c.data == "array_specifier"
                                    for c in kids)  # fmt: skip
                return "initialises a float" if ty == "float" and not is_arr else None
            if kind == "assignment" and expr is kids[2]:
                target = types(kids[0])
                if kids[1] == "=":
                    return "is assigned to a float" if target == "float" else None
                return f"is used in `{kids[1]}` on a float" if is_float_like(target) else None
            if kind == "binary" and str(kids[1]) in _ARITHMETIC:
                other = kids[2] if expr is kids[0] else kids[0]
                if is_float_like(types(other)):
                    return f"is an operand of `{kids[1]}` beside a float"
                return None
            if kind == "arguments":
                return self.argument(expr, parent, parents, model)
            if kind == "jump_statement":
                function = parents.get(id(parent))
                while function is not None and function.data != "function_definition":
                    function = parents.get(id(function))
                if function is None:
                    return None
                ret, name, _ = prototype_parts(function.children[0])  # type: ignore[arg-type]
                return f"is returned from `{name}`, which returns float" if ret == "float" else None
            if kind == "ternary" and expr is not kids[0]:
                other = kids[2] if expr is kids[1] else kids[1]
                if is_float_like(types(other)):
                    return "is a branch of `?:` beside a float"
                expr = parent  # the ternary's own context decides
                continue
            return None

    def argument(
        self, expr: Tree, args: Tree, parents: dict[int, Tree], model: Model
    ) -> str | None:
        call = parents.get(id(args))
        position = next(i for i, a in enumerate(args.children) if a is expr)
        if call is None:
            return None
        if call.data == "constructor":
            ty, arr = type_of_declaration(call.children[0])  # type: ignore[arg-type]
            if arr:
                return "is an element of a float array" if ty == "float" else None
            # struct constructors convert nothing; vector and matrix constructors do
            members = list(model.structs.get(ty, {}).items())
            if len(members) == len(args.children) and members[position][1] == "float":
                return f"initialises the float member `{members[position][0]}` of `{ty}`"
            return None
        callee = call.children[0]
        if call.data != "call" or not (isinstance(callee, Tree) and callee.data == "variable"):
            return None
        name = str(callee.children[0])
        count = len(args.children)
        own = {str(p.children[1]) for p in _prototypes(model.tree)}
        if name in own:  # the file's own function, every overload taking a float
            overloads = [f.params for f in model.functions.get(name, []) if len(f.params) == count]
            if overloads and all(p[position][1] == "float" for p in overloads):
                return f"is passed to a float parameter of `{name}`"
            return None
        if name in FLOAT_ONLY:
            return f"is passed to `{name}`, which takes floats"
        if FLOAT_ARG_AT.get(name) == position:
            return f"is passed as `{name}`'s float bias or level"
        others = [a for i, a in enumerate(args.children) if i != position]
        if name in INT_OVERLOADS and any(is_float_like(model.type_of(a)) for a in others):
            return f"is passed to `{name}` beside a float argument"
        return None


# --- P006 ----------------------------------------------------------------------------------

_NOT_CONSTANT_CALLS = ("texture", "texel", "dFd", "fwidth")


@register
class NonConstantGlobal(Rule):
    """Finds a global variable initialised with something that is not a constant
    expression: a uniform (`iTime`, `iResolution`), another non-const global, a call to a
    function of the file, a texture lookup.

    Why it matters: GLSL ES 3.00 only allows constant expressions in global initialisers
    (desktop GL and some drivers allow more); ShaderToy rejects the shader with
    "non-constant global initializer".

    Example:
        vec2 res = iResolution.xy;
        void mainImage(out vec4 fragColor, in vec2 fragCoord) { ... fragCoord / res ... }

    Fix:
        vec2 res;
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            res = iResolution.xy;
            ...
        }
    """

    code = "P006"
    name = "non-constant-global-initialiser"
    category = "portability"
    severity = "error"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        functions = {str(p.children[1]) for p in _prototypes(ctx.tree)}
        variables: set[str] = set()  # non-const globals declared so far
        for node in ctx.tree.children:
            if not (isinstance(node, Tree) and node.data == "variable_declaration"):
                continue
            words = _qualifier_words(node.children[0])  # type: ignore[arg-type]
            if words & {"uniform", "in", "out"}:
                continue
            for decl in node.children[1:]:
                if not isinstance(decl, Tree):
                    continue
                init = [c for c in decl.children[1:] if isinstance(c, Tree)
                        and c.data != "array_specifier"]  # fmt: skip
                if init:
                    reason = _not_constant(init[0], variables, functions)
                    if reason is not None:
                        name = decl.children[0]
                        message = (f"global `{name}` is initialised with {reason}, which is "
                                   "not a constant expression in GLSL ES 3.00; declare it "
                                   "without a value and assign it in mainImage")  # fmt: skip
                        yield self.report(ctx, init[0], message)
                if "const" not in words:
                    variables.add(str(decl.children[0]))


def _not_constant(init: Tree, variables: set[str], functions: set[str]) -> str | None:
    """What makes an initialiser non-constant, or None (also when unsure)."""
    callees: set[int] = set()
    for node in walk(init):
        if node.data == "call" and isinstance(node.children[0], Tree):
            callee = node.children[0]
            callees.add(id(callee))
            if callee.data == "variable":
                name = str(callee.children[0])
                if name in functions:
                    return f"a call to `{name}` (functions cannot run at global scope)"
                if name.startswith(_NOT_CONSTANT_CALLS):
                    return f"`{name}(...)`"
        elif node.data == "variable" and id(node) not in callees:
            name = str(node.children[0])
            if name in UNIFORM_NAMES or name in ("gl_FragCoord", "gl_FrontFacing"):
                return f"the uniform `{name}`"
            if name in variables:
                return f"the non-const global `{name}`"
    return None


# --- P007 ----------------------------------------------------------------------------------


@register
class ReservedWord(Rule):
    """Finds GLSL ES 3.00 reserved words used as names: `input`, `output`, `sample`,
    `filter`, `common`, `partition`, `active`, `half`, `fixed`, `superp`, `cast`, ...

    Why it matters: these words are reserved for future versions, and using one anywhere
    (a variable, a function, a struct member) is a compile error in GLSL ES, though some
    desktop drivers accept them. Checked on the preprocessed tokens, so it is reported even
    when the file does not parse.

    Example:
        float sample = texture(iChannel0, uv).r;

    Fix:
        float sampled = texture(iChannel0, uv).r;
    """

    code = "P007"
    name = "reserved-word"
    category = "portability"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if ctx.pre is None or ctx.read_problem:
            return
        for number, text in enumerate(ctx.pre.text.split("\n"), start=1):
            if not text.strip():
                continue
            for tok in tokenize(text):
                if tok.kind != "ident" or tok.text not in RESERVED_WORDS:
                    continue
                line = ctx.pre.locate(number).line
                column = tok.col
                if number in ctx.pre.expansions:  # columns moved: find it in the user's line
                    found = re.search(rf"\b{tok.text}\b", ctx.lines[line - 1]) if (
                        0 < line <= len(ctx.lines)) else None  # fmt: skip
                    column = found.start() + 1 if found else 1
                span = (line, column, line, column + len(tok.text))
                message = (f"`{tok.text}` is a reserved word in GLSL ES 3.00 and cannot be "
                           "used as a name; rename it")  # fmt: skip
                yield self.report(ctx, span, message)
