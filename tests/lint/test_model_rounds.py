"""The semantic model keeps a function's pass from the round before when the function is given
the same parameters, globals and callee results again: the model must be the very one that
analysing every function in every round gives."""

from __future__ import annotations

import pytest

from glint.lint.analysis import Model
from glint.lint.context import walk
from glint.lint.options import Options
from glint.lint.precision import CORPUS, valid_files
from glint.lint.runner import build_context

CALL_CHAIN = """
float visibility(float NoV, float a) { return 0.5 / (NoV + a); }
float shade(vec3 n, vec3 v) { float NoV = dot(n, v); return visibility(NoV, 0.1); }
float unused(float x) { return sqrt(x); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 n = normalize(vec3(fragCoord, 1.0));
    fragColor = vec4(shade(n, vec3(0.0, 0.0, 1.0)));
}
"""


class _EveryPass(Model):
    reuse_passes = False


def _values(model: Model) -> list[object]:
    return [model.value_of(node) for node in walk(model.tree)]


def _assert_same(text: str, file: str) -> None:
    ctx = build_context(text, file, Options(glslang=False))
    assert ctx.tree is not None, file
    assert _values(Model(ctx.tree)) == _values(_EveryPass(ctx.tree)), file


def test_kept_passes_give_the_same_model() -> None:
    _assert_same(CALL_CHAIN, "chain.glsl")


@pytest.mark.skipif(not (CORPUS / "glslang-valid.txt").is_file(), reason="no corpus beside")
def test_kept_passes_give_the_same_model_on_real_shaders() -> None:
    for path in valid_files()[::12]:  # every 12th: 36 files, a few seconds
        _assert_same(path.read_text(encoding="utf-8", errors="replace"), str(path))
