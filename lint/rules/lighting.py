"""Lighting: physically wrong shading that compiles and renders, just not as intended. Which
vector is the normal, the light or the view is read from names (see `_lighting_terms`), so
every rule here needs code written with the usual conventions and stays silent otherwise:
a miss is cheaper than a false alarm on correct code."""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from lark import Tree

from ..analysis.model import semantic_model
from ..context import LintContext, Node, walk
from ..finding import Finding, Fix
from . import Rule, register
from ._lighting_terms import (
    Function,
    binary_op,
    call_args,
    call_name,
    calls_in,
    const_value,
    cosine_of,
    function_map,
    functions,
    global_constants,
    is_fresnel_name,
    last_name,
    may_be_negative,
    mentions_normal,
    names_in,
    operands,
    parents,
    resolve,
    root_var,
    schlick_base,
    var_name,
)

_COSINE_TEXT = {"NL": "N·L", "NH": "N·H", "NV": "N·V", "VH": "V·H", "LV": "L·V"}


def _short(ctx: LintContext, node: Node, limit: int = 50) -> str:
    """The node's text for a message: as the user wrote it (macros unexpanded) when the node
    sits on one line without expansions, else as preprocessed."""
    text = ctx.node_text(node)
    if not ctx.has_macros(node):
        line, col, end_line, end_col = ctx.span(node)
        if line == end_line and 0 < line <= len(ctx.lines):
            text = ctx.lines[line - 1][col - 1 : end_col - 1]
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _fresnel_terms(fn: Function) -> Iterator[tuple[Tree, Node]]:
    """Fresnel terms of a function body and the cosine each is fed: calls of functions named
    like Fresnel/Schlick (the argument that is a known cosine), and inline
    `f0 + (1 - f0) * pow(1 - x, 5)` (x)."""
    for node in calls_in(fn.body):
        base = schlick_base(node)
        if base is not None:
            yield node, base
        elif is_fresnel_name(call_name(node)):
            known = [a for a in call_args(node) if cosine_of(a, fn)]
            if len(known) == 1:
                yield node, known[0]


# Functions where Schlick-shaped factors of N·L and N·V are right: diffuse models with a
# retro-reflection or transmission factor (Burley/Disney, Shirley, Ashikhmin).
_DIFFUSE_CONTEXT = re.compile(r"diffuse|burley|disney|lambert|shirley|ashikhmin|^fd", re.I)


@register
class FresnelCosine(Rule):
    """Finds a Fresnel term fed with N·L or N·H, where V·H belongs (for a light; L·H is the
    same angle) or N·V (for environment light).

    Why it matters: Fresnel depends on the angle between the viewer and the microfacet that
    reflects toward it, the half vector. N·L makes surfaces brighten where the light grazes
    them instead of where the eye does, so rim reflections appear on the wrong side.

    Fresnel terms are calls of functions named like Fresnel or Schlick (not Schlick's phase
    function or G1), and the inline form `f0 + (1 - f0) * pow(1 - x, 5)`. Cosines are read
    from names: dot(N, L) with the usual vector names, or precomputed NdotL, NoL, ndl, and
    locals holding them. Diffuse models that multiply Schlick factors of N·L and N·V on
    purpose (Burley, Shirley) are not reported: the function has a matching N·V factor or a
    diffuse name.

    Example:
        float NdotL = max(dot(N, L), 0.0);
        vec3 F = f0 + (1.0 - f0) * pow(1.0 - NdotL, 5.0);

    Fix:
        float VdotH = max(dot(V, H), 0.0);
        vec3 F = f0 + (1.0 - f0) * pow(1.0 - VdotH, 5.0);
    """

    code = "L001"
    name = "fresnel-wrong-cosine"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for fn in functions(ctx):
            if _DIFFUSE_CONTEXT.search(fn.name):
                continue
            terms = [(node, cosine_of(arg, fn), arg) for node, arg in _fresnel_terms(fn)]
            paired = any(kind == "NV" for _, kind, _ in terms)
            for node, kind, arg in terms:
                if kind not in ("NL", "NH") or (kind == "NL" and paired):
                    continue
                if len(call_args(node)) == 3 and any(const_value(a) == 1.0
                                                     for a in call_args(node)):  # fmt: skip
                    continue  # F_Schlick(1.0, f90, NoL): a diffuse scatter factor, not specular
                yield self.report(
                    ctx,
                    arg,
                    f"Fresnel fed with {_COSINE_TEXT[kind]} (`{_short(ctx, arg)}`): use V·H for "
                    "a light (L·H is the same angle), N·V for environment light",
                )


_DIFFUSE_FUNCTION = re.compile(r"diffuse|lambert|brdf|shade|light|illum|^fd|^dif", re.I)
_CLAMPS = {"max", "clamp", "saturate", "abs", "smoothstep", "step", "sqrt", "pow"}
_COLOUR_TYPES = ("vec3", "vec4")


@register
class UnclampedCosine(Rule):
    """Finds N·L or N·V that can be negative multiplied into a colour (or returned as a
    diffuse term) without max, clamp or saturate.

    Why it matters: on the side facing away from the light the cosine is negative, and the
    product subtracts light: other lights and ambient terms go dark or negative, and a later
    pow or sqrt of the sum is undefined.

    The range comes from the semantic model (a value whose interval may be negative) when it
    is available; candidates are dot(N, L) / dot(N, V) calls and locals holding one, in a
    product with a colour (a vec3/vec4 factor or target) or returned bare by a function named
    like diffuse, Lambert, BRDF, shade or light. A cosine that the function compares
    (`if (ndl > 0.0)`) is taken as guarded, and a product with a scalar constant only
    (half-Lambert's `dot(N, L) * 0.5 + 0.5`) is not a lighting term.

    Example:
        vec3 col = albedo * dot(N, L);

    Fix:
        vec3 col = albedo * max(dot(N, L), 0.0);
    """

    code = "L002"
    name = "unclamped-cosine"
    category = "lighting"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = parents(ctx.tree)
        for fn in functions(ctx):
            compared = self._compared(fn)
            for node in walk(fn.body):
                if node.data == "jump_statement" and len(node.children) == 2:
                    candidates = [node.children[1]]
                    # a bare cosine returned by a diffuse-named function is its diffuse term;
                    # elsewhere (`facing(n, v)`) a signed cosine may be the point
                    colour = bool(_DIFFUSE_FUNCTION.search(fn.name))
                elif binary_op(node) == "*" and binary_op(up.get(id(node))) != "*":
                    candidates = operands(node, "*")
                    # a scalar constant scales the cosine (half-Lambert); a colour does not
                    others = [c for c in candidates if const_value(c) is None
                              or (isinstance(c, Tree) and c.data == "constructor")]  # fmt: skip
                    colour = len(others) >= 2 and self._colour(node, candidates, fn, up)
                else:
                    continue
                if not colour:
                    continue
                for operand in candidates:
                    if (
                        self._raw(operand, fn, compared)
                        and not self._clamped(node, up, fn)
                        and may_be_negative(ctx, operand)
                    ):
                        yield self._finding(ctx, operand, fn)

    def _raw(self, node: Node, fn: Function, compared: set[str]) -> bool:
        value = resolve(node, fn)
        if call_name(value) != "dot" or cosine_of(value, fn) not in ("NL", "NV"):
            return False
        return not (names_in(node) & compared)

    def _compared(self, fn: Function) -> set[str]:
        found: set[str] = set()
        for node in walk(fn.body):
            if binary_op(node) in ("<", ">", "<=", ">="):
                found |= names_in(node)
        return found

    def _clamped(self, node: Tree, up: dict[int, Tree], fn: Function) -> bool:
        current: Node = node
        while (parent := up.get(id(current))) is not None and parent is not fn.body:
            if call_name(parent) in _CLAMPS or binary_op(parent) in ("<", ">", "<=", ">="):
                return True
            if parent.data in ("declaration_statement", "expression_statement"):
                break
            current = parent
        return False

    def _colour(self, node: Tree, factors: list[Node], fn: Function, up: dict[int, Tree]) -> bool:
        """Whether the product is a colour: a vec3/vec4 factor, or it goes into one."""
        for factor in factors:
            name = var_name(factor)
            typ = fn.type_of(name) if name else None
            if typ in _COLOUR_TYPES:
                return True
            if (
                isinstance(factor, Tree)
                and factor.data == "constructor"
                and ctx_type(factor) in _COLOUR_TYPES
            ):
                return True
        parent = up.get(id(node))
        while parent is not None and parent.data in ("binary", "unary"):
            parent = up.get(id(parent))
        if parent is None:
            return False
        if parent.data == "declarator":
            return fn.locals.get(str(parent.children[0])) in _COLOUR_TYPES
        if parent.data == "assignment":
            target = root_var(parent.children[0])
            return bool(target) and fn.type_of(target) in _COLOUR_TYPES  # type: ignore[arg-type]
        return False

    def _finding(self, ctx: LintContext, operand: Node, fn: Function) -> Finding:
        kind = _COSINE_TEXT[cosine_of(resolve(operand, fn), fn) or "NL"]
        fix = None
        if call_name(operand) == "dot":
            edit = ctx.replace(operand, f"max({ctx.node_text(operand)}, 0.0)")
            if edit is not None:
                fix = Fix("clamp the cosine at 0", (edit,), "unsafe")
        return self.report(
            ctx,
            operand,
            f"{kind} (`{_short(ctx, operand)}`) is negative facing away and is used unclamped "
            "in a lighting term; take max(..., 0.0)",
            fix,
        )


def ctx_type(node: Tree) -> str:
    spec = node.children[0]
    return " ".join(str(t) for t in spec.children) if isinstance(spec, Tree) else ""


# --- roughness --------------------------------------------------------------------------------

_GGX_LIKE = re.compile(
    r"ggx|smith|trowbridge|beckmann|distribution|visibility|geometry|ndf|^d_|^v_|^g_|g1", re.I
)
_POWER_BY_NAME = [
    (re.compile(r"^(perceptual_?)?rough(ness)?(_?perceptual)?$", re.I), 1),
    (re.compile(r"^(a|alpha|alpha_?g|linear_?roughness)$", re.I), 2),
    (re.compile(r"^(a2|a_2|asq|asqr|alpha_?2|alpha_?sq|alpha_?sqr|alpha_?squared)$", re.I), 4),
]
_POWER_TEXT = {1: "perceptual roughness", 2: "α = roughness²", 4: "α² = roughness⁴"}


def _name_power(name: str | None) -> int | None:
    if not name:
        return None
    for pattern, power in _POWER_BY_NAME:
        if pattern.match(name):
            return power
    return None


def roughness_power(node: Node, fn: Function | None, depth: int = 5) -> int | None:
    """The power of perceptual roughness an expression holds (1, 2, 4 ...), from names and
    products; None when unknown."""
    if depth <= 0 or not isinstance(node, Tree):
        return None
    if node.data in ("variable", "field"):
        value = resolve(node, fn, 1) if node.data == "variable" else node
        if value is not node:
            found = roughness_power(value, fn, depth - 1)
            if found is not None:
                return found
        return _name_power(last_name(node))
    name = call_name(node)
    if name in ("max", "min", "clamp"):
        inner = [a for a in call_args(node) if const_value(a) is None]
        return roughness_power(inner[0], fn, depth - 1) if len(inner) == 1 else None
    if name == "pow":
        args = call_args(node)
        base, exponent = roughness_power(args[0], fn, depth - 1), const_value(args[1])
        if base is not None and exponent is not None and float(exponent).is_integer():
            return base * int(exponent)
        return None
    if binary_op(node) == "*":
        powers = [roughness_power(f, fn, depth - 1) for f in operands(node, "*")]
        if any(p is None for p in powers):
            return None
        return sum(powers)  # type: ignore[arg-type]
    return None


@register
class RoughnessSquaring(Rule):
    """Finds roughness squared twice, or not at all, on the way into a GGX or Smith term: the
    argument holds a different power of roughness than the parameter's name says.

    Why it matters: GGX and Smith take α = roughness² (Burley's remapping). Passing α where
    the function squares again gives α² (surfaces look much glossier than the roughness
    slider says); passing perceptual roughness where α is expected makes everything rougher.

    What is decided statically: the callee is a function of the file named like a
    distribution or visibility term (GGX, Smith, Beckmann, D_, V_, G_, G1, distribution,
    visibility); its parameter says what it expects by name (roughness/perceptualRoughness:
    roughness; alpha/a/linearRoughness: α; a2/alpha2/alphaSq: α²); the argument's power of
    roughness is known from names and products (`r * r` with r = roughness is α, `a * a` with
    a = α is α²). Anything else (`k`, `m`, arbitrary expressions) is not judged.

    Example:
        float a = roughness * roughness;
        float D = D_GGX(NoH, a * a);  // D_GGX(float NoH, float a) squares a itself

    Fix:
        float a = roughness * roughness;
        float D = D_GGX(NoH, a);
    """

    code = "L003"
    name = "roughness-squaring"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        defined = function_map(ctx)
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                callee = defined.get(call_name(node) or "")
                if callee is None or not _GGX_LIKE.search(callee.name):
                    continue
                for param, arg in zip(callee.param_order, call_args(node), strict=False):
                    expected = _name_power(param)
                    got = roughness_power(arg, fn)
                    if expected is None or got is None or got == expected:
                        continue
                    how = "squared once too often" if got > expected else "not squared"
                    yield self.report(
                        ctx,
                        arg,
                        f"roughness {how}: `{_short(ctx, arg)}` is "
                        f"{_POWER_TEXT.get(got, f'roughness^{got}')} but {callee.name}'s "
                        f"parameter `{param}` is {_POWER_TEXT[expected]}",
                    )


# --- Blinn-Phong next to PBR ------------------------------------------------------------------

_PBR_NAME = re.compile(r"ggx|smith|cook|torrance|beckmann|trowbridge", re.I)
_NORM_NAME = re.compile(r"norm(?!al)", re.I)


def _has_pbr(ctx: LintContext) -> bool:
    for fn in functions(ctx):
        if _PBR_NAME.search(fn.name) or is_fresnel_name(fn.name):
            return True
        for node in calls_in(fn.body):
            if schlick_base(node) is not None or is_fresnel_name(call_name(node)):
                return True
    return False


@register
class UnnormalizedBlinnPhong(Rule):
    """Finds an unnormalized Blinn-Phong lobe, pow(N·H, n) without its (n + 8)/(8π) or
    (n + 2)/(2π) factor, in a shader that also has physically based terms (Fresnel, GGX,
    Smith, Cook-Torrance).

    Why it matters: the peak of pow(N·H, n) is 1 whatever n is, so the energy it reflects
    falls as the lobe narrows: next to energy-conserving GGX or Fresnel-weighted terms,
    glossy surfaces come out too dark and rough ones too bright. On its own, tuned by eye,
    Blinn-Phong is fine and is not reported.

    The lobe is pow(x, n) with x a known N·H (names and dot(N, H)) and n not 5 (that is a
    Fresnel shape); it counts as normalized when `n + 8`, `n + 2` (or + 1, 4, 6) appears
    anywhere in the shader, or a name like normFactor multiplies it in the same function.

    Example:
        float spec = pow(NoH, shininess);
        vec3 col = F * spec;

    Fix:
        float spec = (shininess + 8.0) / (8.0 * PI) * pow(NoH, shininess);
        vec3 col = F * spec;
    """

    code = "L004"
    name = "unnormalized-blinn-phong"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        lobes = []
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                if call_name(node) != "pow" or len(call_args(node)) != 2:
                    continue
                base, exponent = call_args(node)
                if const_value(exponent) == 5.0 or cosine_of(base, fn) != "NH":
                    continue
                if not self._normalized(ctx, fn, exponent):
                    lobes.append((node, exponent))
        if not lobes or not _has_pbr(ctx):
            return
        for node, exponent in lobes:
            n = _short(ctx, exponent, 20)
            yield self.report(
                ctx,
                node,
                f"Blinn-Phong lobe without its normalization next to physically based terms: "
                f"multiply by ({n} + 8.0) / (8.0 * PI)",
            )

    def _normalized(self, ctx: LintContext, fn: Function, exponent: Node) -> bool:
        wanted = " ".join(ctx.node_text(exponent).split())
        assert ctx.tree is not None
        for node in walk(ctx.tree):
            if binary_op(node) == "+":
                parts = operands(node, "+")
                texts = {" ".join(ctx.node_text(p).split()) for p in parts}
                if wanted in texts and any(const_value(p) in (1.0, 2.0, 4.0, 6.0, 8.0)
                                           for p in parts):  # fmt: skip
                    return True
        return any(_NORM_NAME.search(n) for n in names_in(fn.body))


# --- the output: gamma and tone mapping -------------------------------------------------------

_ENCODE_NAME = re.compile(r"gamma|srgb|outputtransfer|encode|todisplay", re.I)
_DECODE_NAME = re.compile(r"tolinear|linearize|degamma|decode|srgb2lin|srgbtolin|removegamma", re.I)
_TONEMAP_NAME = re.compile(
    r"tone_?map|aces|reinhard|filmic|uncharted|hable|agx|lottes|uchimura|exposure", re.I
)


def _main(ctx: LintContext) -> tuple[Function, str] | None:
    """mainImage and the name of its colour output."""
    for fn in functions(ctx):
        if fn.name == "mainImage":
            for name in fn.param_order:
                if "out" in fn.params[name][0]:
                    return fn, name
    return None


def _vector(ctx: LintContext, node: Node) -> bool:
    """Whether the expression is a vector (a colour), by the model's type."""
    return (semantic_model(ctx).type_of(node) or "").startswith("vec")


class _Output:
    """What a shader does to colour on its way out: which functions encode for the display
    (gamma/sRGB), and whether something tone maps."""

    def __init__(self, ctx: LintContext) -> None:
        self.ctx = ctx
        self.defined = function_map(ctx)
        self.encoders = {f.name for f in functions(ctx) if self._encoder(f)}

    def _encoder(self, fn: Function) -> bool:
        if _DECODE_NAME.search(fn.name):
            return False
        if _ENCODE_NAME.search(fn.name) and fn.name != "mainImage":
            return True
        for node in walk(fn.body):
            if node.data == "jump_statement" and len(node.children) == 2:
                value = self._peel(resolve(node.children[1], fn))
                if self.gamma_of(value, fn, direct=True) is not None:
                    return True
        return False

    def _peel(self, node: Node) -> Node:
        while isinstance(node, Tree) and node.data == "constructor" and call_args(node):
            node = call_args(node)[0]
        return node

    def gamma_of(self, node: Node, fn: Function | None, direct: bool = False) -> Node | None:
        """For a display encoding (pow by about 1/2.2, sqrt of a colour, a call of an encoding
        function) the colour it encodes, else None."""
        name = call_name(node)
        if name is None:
            return None
        args = call_args(node)  # type: ignore[arg-type]
        if name == "pow" and len(args) == 2:
            value = const_value(args[1])
            text = self.ctx.node_text(args[1]).lower()
            if (value is not None and 0.38 <= value <= 0.5) or "gamma" in text:
                return args[0]
        if name == "sqrt" and len(args) == 1 and _vector(self.ctx, args[0]):
            return args[0]
        if not direct and name in self.encoders and args:
            return args[0]
        return None

    def any_gamma(self) -> bool:
        if self.encoders:
            return True
        return any(self.gamma_of(n, fn) is not None for fn in functions(self.ctx)
                   for n in calls_in(fn.body))  # fmt: skip

    def any_tonemap(self) -> bool:
        for fn in functions(self.ctx):
            if _TONEMAP_NAME.search(fn.name):
                return True
            for node in walk(fn.body):
                if _TONEMAP_NAME.search(call_name(node) or "") or self._tonemap_form(node):
                    return True
        return False

    def _tonemap_form(self, node: Tree) -> bool:
        text = self.ctx.node_text
        if binary_op(node) == "/":
            top = " ".join(text(node.children[0]).split())
            parts = operands(node.children[2], "+")
            # x / (1 + x), x / (x + k): Reinhard and its variants
            if len(parts) >= 2 and top in {" ".join(text(p).split()) for p in parts}:
                return True
        if binary_op(node) == "-" and const_value(node.children[0]) == 1.0:
            return call_name(node.children[2]) == "exp"  # 1 - exp(-k x): exponential
        if call_name(node) in ("clamp", "min", "saturate", "smoothstep"):
            return False
        return False


def _output_writes(fn: Function, out: str) -> list[Tree]:
    return [n for n in walk(fn.body) if n.data == "assignment" and root_var(n.children[0]) == out]


@register
class MissingOutputTransfer(Rule):
    """Finds a lit shader that writes linear colour to the output without a gamma or sRGB
    encoding anywhere.

    Why it matters: lighting is computed in linear units, but the display expects sRGB-
    encoded values; without the encoding midtones come out far too dark and the falloff of
    light looks harsh. ShaderToy does not encode for you.

    A shader counts as lit when it takes a dot product with a normal (2D art and image
    effects are left alone: their colours are already display values). An encoding is a pow
    by an exponent of 0.38 to 0.5 (1/2.2, 0.4545, 1/2.4), a pow by something named gamma, a
    sqrt of a colour (gamma 2), or a function named like gamma/sRGB/outputTransfer; anywhere
    in the shader counts, since where it sits is for L006 to judge. A buffer pass that hands
    linear colour to the Image pass is correct without an encoding: suppress L005 there
    (`// glint: file-ignore[L005, L007]`).

    Example:
        col = albedo * max(dot(n, l), 0.0);
        fragColor = vec4(col, 1.0);

    Fix:
        col = albedo * max(dot(n, l), 0.0);
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
    """

    code = "L005"
    name = "missing-output-transfer"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = _main(ctx)
        if found is None or not mentions_normal(ctx) or _Output(ctx).any_gamma():
            return
        fn, out = found
        writes = _output_writes(fn, out)
        if writes:
            yield self.report(
                ctx,
                writes[-1],
                f"lit colour reaches `{out}` without a gamma/sRGB encoding: apply "
                "pow(col, vec3(1.0 / 2.2)) (or an sRGB curve) before writing it",
            )


@register
class DoubleGamma(Rule):
    """Finds a display encoding (gamma or sRGB) applied to colour that is already encoded.

    Why it matters: encoding twice is gamma 4.84 instead of 2.2: the image looks washed out
    and flat, with lifted blacks. It typically happens when a helper encodes and mainImage
    encodes again.

    Traced in source order through mainImage: a variable assigned an encoded value stays
    encoded while it is reassigned from itself; encoding it again (directly, or through a
    function whose result is an encoded value) is reported, as is an encoding nested in
    another anywhere. Branches are not told apart.

    Example:
        col = pow(col, vec3(0.4545));
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);

    Fix:
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
    """

    code = "L006"
    name = "double-gamma"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        output = _Output(ctx)
        reported: set[int] = set()
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                inner = output.gamma_of(node, fn)
                if inner is not None and any(
                    output.gamma_of(n, fn) is not None for n in calls_in(inner)
                ) and id(node) not in reported:  # fmt: skip
                    reported.add(id(node))
                    yield self._finding(ctx, node)
        found = _main(ctx)
        if found is None:
            return
        fn, _ = found
        encoded: set[str] = set()
        for node in walk(fn.body):
            if node.data == "declarator" and len(node.children) > 1:
                target, value = str(node.children[0]), node.children[-1]
            elif node.data == "assignment" and str(node.children[1]) == "=":
                target, value = root_var(node.children[0]) or "", node.children[2]
            else:
                continue
            for call in calls_in(value):
                inner = output.gamma_of(call, fn)
                if inner is not None and names_in(inner) & encoded and id(call) not in reported:
                    reported.add(id(call))
                    yield self._finding(ctx, call)
            top = output._peel(value)
            if output.gamma_of(top, fn) is not None or names_in(value) & encoded:
                encoded.add(target)
            else:
                encoded.discard(target)

    def _finding(self, ctx: LintContext, node: Node) -> Finding:
        return self.report(
            ctx,
            node,
            f"`{_short(ctx, node)}` encodes for the display a colour that is already encoded "
            "(gamma applied twice)",
        )


def _factors(node: Node) -> tuple[list[Node], list[Node]]:
    """Numerators and denominators of a chain of * and / (`a * b / c` -> [a, b], [c])."""
    top: list[Node] = []
    bottom: list[Node] = []
    stack: list[tuple[Node, bool]] = [(node, True)]
    while stack:
        item, up = stack.pop()
        op = binary_op(item)
        if op in ("*", "/"):
            assert isinstance(item, Tree)
            stack.append((item.children[0], up))
            stack.append((item.children[2], up if op == "*" else not up))
        else:
            (top if up else bottom).append(item)
    return top, bottom


def _light_terms(fn: Function, up: dict[int, Tree]) -> list[Node]:
    """Whole products (chains of * and /) that carry a lighting cosine or a specular lobe."""
    terms = []
    for node in walk(fn.body):
        if binary_op(node) not in ("*", "/") or binary_op(up.get(id(node))) in ("*", "/"):
            continue
        top, _ = _factors(node)
        if any(cosine_of(f, fn) in ("NL", "NH", "NV") or _lobe(f, fn) for f in top):
            terms.append(node)
    return terms


def _bound(node: Node, fn: Function, names: dict[str, float], depth: int = 6) -> float | None:
    """A rough upper bound of a light term from its constants: cosines, lobes and values the
    code does not say are taken as at most 1, so only explicit intensities raise it; None
    when a divisor is not a constant."""
    if depth <= 0 or not isinstance(node, Tree):
        return 1.0
    value = const_value(node, names)
    if value is not None:
        return abs(value)
    if node.data == "constructor":
        values = [const_value(a) for a in call_args(node)]
        known = [abs(v) for v in values if v is not None]
        return max(known) if known and len(known) == len(values) else 1.0
    if node.data == "variable":
        resolved = resolve(node, fn, 1)
        return 1.0 if resolved is node else _bound(resolved, fn, names, depth - 1)
    op = binary_op(node)
    if op in ("*", "/"):
        top, bottom = _factors(node)
        result = 1.0
        for factor in top:
            b = _bound(factor, fn, names, depth - 1)
            if b is None:
                return None
            result *= b
        for factor in bottom:
            divisor = const_value(factor, names)
            if divisor is None:
                divisor = _bound(factor, fn, names, depth - 1) if binary_op(factor) == "+" else None
            if not divisor:
                return None
            result /= divisor
        return result
    if op == "+":
        parts = [_bound(p, fn, names, depth - 1) for p in operands(node, "+")]
        return None if any(p is None for p in parts) else sum(parts)  # type: ignore[arg-type]
    if op == "-":
        return _bound(node.children[0], fn, names, depth - 1)
    if call_name(node) == "clamp" and len(call_args(node)) == 3:
        hi = const_value(call_args(node)[2])
        return abs(hi) if hi is not None else 1.0
    return 1.0


def _lobe(node: Node, fn: Function) -> bool:
    if call_name(node) == "pow":
        return cosine_of(call_args(node)[0], fn) in ("NH", "LV")  # type: ignore[arg-type]
    return False


@register
class HdrWithoutTonemap(Rule):
    """Finds lighting that can exceed 1 written to the output without a tone map.

    Why it matters: the display clips each channel at 1, so bright highlights and sums of
    lights lose their hue (a saturated orange light clips to yellow, then white) and detail
    flattens. A tone map (x / (1 + x), an ACES fit, 1 − exp(−x)) rolls highlights off.

    Evidence that values exceed 1, in a lit shader: a light term (a product with N·L, N·H or
    N·V, or a pow lobe) whose bound is above 1, or two or more light terms summed in one
    function whose bounds add up to more than 1. The bound is the semantic model's when it is
    finite; otherwise the product of the term's constants (an intensity such as `2.0 *
    sunColor`, `vec3(1.3, 1.0, 0.7)`, divided by the constant divisors such as π), with
    cosines, lobes and values the code does not spell out taken as at most 1.
    Decision on clamp: clamp(col, 0.0, 1.0) or min(col, 1.0) is not a tone map, but it shows
    that the author chose to clip, so it is not reported either; this rule is for code that
    never considered the range.

    Example:
        col = 2.0 * albedo * max(dot(n, l), 0.0) + spec;
        fragColor = vec4(pow(col, vec3(0.4545)), 1.0);

    Fix:
        col = 2.0 * albedo * max(dot(n, l), 0.0) + spec;
        col = col / (1.0 + col);
        fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
    """

    code = "L007"
    name = "hdr-without-tonemap"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = _main(ctx)
        if found is None or not mentions_normal(ctx):
            return
        output = _Output(ctx)
        if output.any_tonemap():
            return
        fn, out = found
        writes = _output_writes(fn, out)
        if not writes or self._clipped(ctx):
            return
        evidence = self._evidence(ctx)
        if evidence:
            yield self.report(
                ctx,
                writes[-1],
                f"lighting can exceed 1 ({evidence}) and is written to `{out}` without a tone "
                "map; the display clips it (try col / (1.0 + col) before the gamma)",
            )

    def _clipped(self, ctx: LintContext) -> bool:
        found = _main(ctx)
        assert found is not None
        fn, _ = found
        for node in calls_in(fn.body):
            name = call_name(node)
            args = call_args(node)
            if name in ("clamp", "saturate") and args and _vector(ctx, args[0]):
                return True
            if name == "min" and any(const_value(a) == 1.0 for a in args):
                return True
        return False

    def _evidence(self, ctx: LintContext) -> str:
        assert ctx.tree is not None
        up = parents(ctx.tree)
        for fn in functions(ctx):
            terms = _light_terms(fn, up)
            for term in terms:
                hi = self._hi(ctx, term, fn)
                if hi is not None and hi > 1.0:
                    return f"`{_short(ctx, term, 40)}` reaches about {hi:.3g}"
            sums = self._summed(ctx, fn, terms)
            if sums:
                return sums
        return ""

    def _hi(self, ctx: LintContext, node: Node, fn: Function) -> float | None:
        """The model's finite upper bound, else the bound from the code's constants."""
        hi = _bounded_hi(ctx, node)
        return hi if hi is not None else _bound(node, fn, global_constants(ctx))

    def _summed(self, ctx: LintContext, fn: Function, terms: list[Node]) -> str:
        ids = {id(t) for t in terms}

        def carries(node: Node) -> bool:
            return any(id(n) in ids for n in walk(node)) if isinstance(node, Tree) else False

        def may_exceed(parts: list[Node]) -> bool:
            his = [self._hi(ctx, p, fn) for p in parts]
            return sum(1.0 if h is None else h for h in his) > 1.0

        per_target: dict[str, list[Node]] = {}
        for node in walk(fn.body):
            if binary_op(node) == "+":
                parts = operands(node, "+")
                if sum(1 for p in parts if carries(p)) >= 2 and may_exceed(parts):
                    return f"light terms summed in {fn.name}"
            if node.data == "assignment" and str(node.children[1]) == "+=":
                target = root_var(node.children[0]) or ""
                if carries(node.children[2]):
                    added = per_target.setdefault(target, [])
                    added.append(node.children[2])
                    if len(added) >= 2 and may_exceed(added):
                        return f"light terms accumulated into `{target}` in {fn.name}"
        return ""


def _bounded_hi(ctx: LintContext, node: Node) -> float | None:
    """The model's upper bound of the value when it has a finite one, else None."""
    hi = semantic_model(ctx).range_of(node).hi
    return float(hi) if math.isfinite(hi) else None


# --- energy split ------------------------------------------------------------------------------

_DIFFUSE_NAME = re.compile(
    r"^(diffuse|diff|dif|fd|lambert|albedo|base_?colou?r|basecol|base|kd_?albedo)$", re.I
)
_DIFFUSE_CALL = re.compile(r"diffuse|lambert|burley|oren_?nayar|^fd", re.I)
_SPLIT_NAME = re.compile(
    r"^(kd|k_d|kdiffuse|diffusecolou?r|cdiff|c_diff|diffuse_colou?r|diffusealbedo)$", re.I
)
_METAL_NAME = re.compile(r"metal(lic|ness)?", re.I)


@register
class EnergyNotSplit(Rule):
    """Finds a diffuse term added to a Fresnel-weighted specular term without being scaled by
    what the Fresnel term does not reflect, (1 − F), or by (1 − metallic).

    Why it matters: light reflected at the surface (F) is not available to scatter inside it.
    Adding full diffuse to Fresnel specular reflects more than arrives at grazing angles, and
    a metal (which has no diffuse) keeps a coloured diffuse glow.

    Decided per sum, `diffuse + specular` in one expression (including locals it reads):
    the specular side contains a Fresnel call or the inline Schlick form, the diffuse side is
    named like diffuse, Lambert, albedo or base colour, or is a product with N·L and no
    specular lobe; the split is any factor `1 - x` with x
    Fresnel or metallic, a kD factor, or an already split colour (diffuseColor, cdiff), also
    inside the diffuse function it calls. Sums built by separate `+=` statements are not
    followed.

    Example:
        vec3 F = fresnelSchlick(f0, VoH);
        vec3 col = albedo / PI * NoL + F * D * Vis * NoL;

    Fix:
        vec3 F = fresnelSchlick(f0, VoH);
        vec3 col = (1.0 - F) * (1.0 - metallic) * albedo / PI * NoL + F * D * Vis * NoL;
    """

    code = "L008"
    name = "energy-not-split"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = parents(ctx.tree)
        defined = function_map(ctx)
        for fn in functions(ctx):
            fresnel_vars = self._fresnel_vars(fn)
            for node in walk(fn.body):
                if binary_op(node) != "+" or binary_op(up.get(id(node))) == "+":
                    continue
                parts = operands(node, "+")
                spec = [p for p in parts if self._has_fresnel(p, fn, fresnel_vars)]
                diffuse = [p for p in parts if p not in spec and self._diffuse(p, fn)]
                if not spec or not diffuse:
                    continue
                for part in diffuse:
                    if not self._split(part, fn, fresnel_vars, defined):
                        yield self.report(
                            ctx,
                            part,
                            f"diffuse `{_short(ctx, part, 40)}` is added to Fresnel specular "
                            "without (1 - F) or (1 - metallic): reflected light is counted "
                            "twice",
                        )

    def _fresnel_vars(self, fn: Function) -> set[str]:
        found = set()
        for name, value in fn.init.items():
            if fn.value_of(name) is not None and self._has_fresnel(value, fn, set()):
                found.add(name)
        return found

    def _has_fresnel(self, node: Node, fn: Function, fresnel_vars: set[str]) -> bool:
        if names_in(node) & fresnel_vars:
            return True
        return any(schlick_base(c) is not None or is_fresnel_name(call_name(c))
                   for c in calls_in(node))  # fmt: skip

    def _expand(self, node: Node, fn: Function, depth: int = 3) -> list[Node]:
        """The node and the values of the locals it reads (a few levels)."""
        found = [node]
        if depth > 0:
            for name in names_in(node):
                value = fn.value_of(name)
                if value is not None:
                    found += self._expand(value, fn, depth - 1)
        return found

    def _diffuse(self, node: Node, fn: Function) -> bool:
        top, _ = _factors(node)
        if any(cosine_of(f, fn) == "NL" for f in top) and not any(_lobe(f, fn) for f in top):
            return True  # a colour times N·L with no specular lobe: Lambert by another name
        for part in self._expand(node, fn):
            if any(_DIFFUSE_NAME.match(n) for n in names_in(part)):
                return True
            if any(_DIFFUSE_NAME.match(str(f.children[-1])) for f in walk(part)
                   if f.data == "field") if isinstance(part, Tree) else False:  # fmt: skip
                return True
            if any(_DIFFUSE_CALL.search(call_name(c) or "") for c in calls_in(part)):
                return True
        return False

    def _split(
        self, node: Node, fn: Function, fresnel_vars: set[str], defined: dict[str, Function]
    ) -> bool:
        for part in self._expand(node, fn):
            if not isinstance(part, Tree):
                continue
            for sub in walk(part):
                if self._one_minus(sub, fn, fresnel_vars):
                    return True
                leaf = last_name(sub)
                if leaf and _SPLIT_NAME.match(leaf):
                    return True
                callee = defined.get(call_name(sub) or "")
                if callee is not None and callee is not fn:
                    args = call_args(sub)
                    if any(names_in(a) & fresnel_vars for a in args):
                        return True  # F handed to the diffuse function: it splits inside
                    if any(self._one_minus(s, callee, set()) or _SPLIT_NAME.match(
                            last_name(s) or "") for s in walk(callee.body)):  # fmt: skip
                        return True
        return False

    def _one_minus(self, node: Tree, fn: Function, fresnel_vars: set[str]) -> bool:
        if binary_op(node) != "-" or const_value(node.children[0]) != 1.0:
            return False
        right = node.children[2]
        names = names_in(right)
        if names & fresnel_vars or any(_METAL_NAME.search(n) for n in names):
            return True
        if isinstance(right, Tree) and any(
            _METAL_NAME.search(str(f.children[-1])) for f in walk(right) if f.data == "field"
        ):
            return True
        return self._has_fresnel(right, fn, fresnel_vars) or any(
            n.upper().startswith("F") or n.lower().startswith("ks") for n in names
        )
