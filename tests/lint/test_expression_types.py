"""The typing pass (analysis/expression_types.py) answers the rules that ask only an
expression's type, in place of the semantic model, which costs far more. It must give the very
type the model gives, for every node of a file."""

from __future__ import annotations

import pytest

from glint.lint.analysis import Model
from glint.lint.analysis.expression_types import ExpressionTypes
from glint.lint.context import indexed, walk
from glint.lint.options import Options
from glint.lint.precision import CORPUS
from glint.lint.runner import build_context

# Scopes that a flat table of names would get wrong: shadowing in blocks and loops, a global
# declared after the function that reads its name, an initializer that reads the name it
# declares, a while-condition declaration, switch bodies, overloads by arity, a function
# defined after its caller, struct members and arrays of them, and what ?: and = take.
SCOPES = """
struct Ray { vec3 o; vec3 d; };
struct Hit { Ray ray; float t[2]; };
float x = 1.0;
float later(vec2 p);
float later(vec2 p, int n) { return float(n); }
vec3 shade(Hit h, int i) {
    vec2 x = vec2(x);                    // the global float, then a local vec2
    for (int x = 0; x < 3; x++) { h.t[0] += float(x); }
    ivec3 k = ivec3(x.xyx);
    { bvec2 x = bvec2(true); k.x += x.x ? 1 : 0; }
    while (bool go = k.x > 0) { k.x--; }
    switch (i) { case 0: mat3 m = mat3(1.0); k.y = int(m[0].x); break; default: break; }
    float y = y;                         // reads a name nobody has declared yet
    float s = later(x) + later(x, 2) + h.ray.o.x + h.t[1];
    return s > 0.0 ? h.ray.d : vec3(k);
}
float y = 2.0;
float later(vec2 p) { return y + p.x + iTime; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    Hit h = Hit(Ray(vec3(0.0), vec3(0.0, 0.0, 1.0)), float[2](0.0, 1.0));
    vec3 c = shade(h, int(fragCoord.x)) * (fragColor.x = 0.5);
    fragColor = vec4(c, length(fragCoord) < 1.0 ? 1 : 0) + iResolution.xyxy / iChannelTime[0];
}
"""


def _assert_same_types(text: str, file: str) -> int:
    ctx = build_context(text, file, Options(glslang=False))
    assert ctx.tree is not None, file
    with indexed(ctx.tree):
        model, typed = Model(ctx.tree), ExpressionTypes(ctx.tree)
        nodes = list(walk(ctx.tree))
        wrong = [(n.data, ctx.node_text(n)) for n in nodes if model.type_of(n) != typed.type_of(n)]
    assert not wrong, f"{file}: {wrong[:5]}"
    return sum(typed.type_of(n) is not None for n in nodes)


def test_types_agree_with_the_model_on_tricky_scopes() -> None:
    typed = _assert_same_types(SCOPES, "scopes.glsl")
    assert typed > 100  # the comparison saw typed expressions, not a tree of unknowns


@pytest.mark.skipif(not (CORPUS / "shadertoy").is_dir(), reason="no corpus beside")
def test_types_agree_with_the_model_on_real_shaders() -> None:
    files = sorted((CORPUS / "shadertoy").glob("*.glsl"))[::3]  # about 150 files, a few seconds
    for path in files:
        _assert_same_types(path.read_text(encoding="utf-8", errors="replace"), path.name)
