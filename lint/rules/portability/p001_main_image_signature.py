"""P001 main-image-signature."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.ast import FunctionPrototype, variable_name
from glint.compiler.target.shadertoy import is_complete

from ...analysis.syntax import parameter_parts, prototype_parts
from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._common import function_prototypes, signature_problem


@register
class MainImageSignature(Rule):
    """Finds an Image-tab shader whose entry point is not `void mainImage(out vec4 fragColor, in
    vec2 fragCoord)` (names are free, `in` optional): a wrong parameter list or return type, or no
    mainImage in code that writes the pixel through `gl_FragColor`/`gl_FragCoord`.

    A file without mainImage that uses neither is taken for library code (a Common tab, a file of
    helpers) and not reported, and one that defines `main` or opens with `#version` is a complete
    shader, which needs no mainImage.

    Why is this bad?
        ShaderToy appends a `main` that calls mainImage with exactly these arguments; any other
        signature fails to compile there with an error in code you did not write.

    Example:
        void mainImage(out vec3 color, vec2 uv) { color = vec3(uv, 0.0); }

    Use instead:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) { ... }

    Fix safety:
        No fix: the body has to change with the signature.

    References:
        - ShaderToy's How To (https://www.shadertoy.com/howto): the mainImage signature
    """

    code = "P001"
    name = "main-image-signature"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if ctx.tab.is_common:
            return  # a Common tab has no mainImage: ShaderToy gives it a `main` of its own
        protos = function_prototypes(ctx.tree)
        names = {FunctionPrototype(p).name for p in protos}
        if "main" in names or is_complete(ctx.text):
            return
        mains = [p for p in protos if FunctionPrototype(p).name == "mainImage"]
        problems = []
        for proto in mains:
            ret, name, params = prototype_parts(proto)
            problem = signature_problem(ret, params)
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
        near = [p.name_token for p in map(FunctionPrototype, protos)
                if p.name.lower().replace("_", "") == "mainimage"]  # fmt: skip
        if near:
            yield self.report(ctx, near[0], f"`{near[0]}` is not `mainImage`: ShaderToy "
                              "calls `mainImage`, with this capitalisation")  # fmt: skip
            return
        uses = next((n for n in ctx.nodes("variable")
                     if variable_name(n) in ("gl_FragColor", "gl_FragData", "gl_FragCoord")),
                    None)  # fmt: skip
        if uses is not None:
            yield self.report(
                ctx, uses, "no mainImage: ShaderToy calls `void mainImage(out vec4 fragColor, "
                "in vec2 fragCoord)`; move the pixel code into it",
            )  # fmt: skip
