"""The ranges the semantic model reports, held to values sampled by running the same code.

Each case is a GLSL function `f` and the ranges of its parameters. The model learns the
parameters' ranges from a call in mainImage with arguments of exactly those ranges; glint's own
GLSL evaluator (compiler/evaluator) then runs `f` on many inputs drawn from the same ranges. The
true (sampled) range must lie inside the reported one (soundness), and where the model gives a
finite range it must be no more than 10 times as wide as the sampled one (plausibility: a value
noise in [0, 1) shown as [-4, 5] tells the reader nothing).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from glint.compiler.evaluator import evaluate
from glint.lint.analysis import semantic_model
from glint.lint.analysis.ranges import Interval
from glint.lint.options import Options
from glint.lint.runner import build_context

SAMPLES = 4000
WIDER = 10.0  # the most the reported range may exceed the sampled one by, as a factor


@dataclass(frozen=True)
class Param:
    """A parameter: a float in [lo, hi], or a unit vector (`unit`), or a vecN in [lo, hi]^N."""

    type: str
    lo: float = 0.0
    hi: float = 1.0
    unit: bool = False

    def argument(self, k: int) -> str:
        """An argument expression whose model range is exactly this parameter's."""
        t = f"fract(fragCoord.x * {k + 1}.37)"  # [0, 1): the model knows fract
        if self.unit:
            n = int(self.type[-1])
            comps = ", ".join(f"sin(fragCoord.x * {k + i + 2}.1)" for i in range(n))
            return f"normalize({self.type}({comps}))"
        if self.type == "float":
            return f"mix({self.lo!r}, {self.hi!r}, {t})"
        return f"mix({self.type}({self.lo!r}), {self.type}({self.hi!r}), {self.type}({t}))"

    def sample(self, rng: np.random.Generator) -> np.ndarray:
        if self.type == "float":
            return rng.uniform(self.lo, self.hi, SAMPLES)
        n = int(self.type[-1])
        if self.unit:
            v = rng.normal(size=(SAMPLES, n))
            return v / np.linalg.norm(v, axis=1, keepdims=True)
        return rng.uniform(self.lo, self.hi, (SAMPLES, n))


NOISE = """
float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float noise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), u.x),
               mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0, 1.0)), u.x), u.y);
}
"""

ROTATE = "mat2 rot(float a) { float c = cos(a), s = sin(a); return mat2(c, s, -s, c); }\n"

F = Param("float")
UNIT3 = Param("vec3", unit=True)

CASES: dict[str, tuple[str, list[Param]]] = {
    "value noise": (NOISE + "float f(vec2 p) { return noise(p); }", [Param("vec2", -50, 50)]),
    "fbm of value noise": (
        NOISE + "float f(vec2 p) { return 0.5 * noise(p) + 0.25 * noise(p * 2.0)"
        " + 0.125 * noise(p * 4.0); }",
        [Param("vec2", -50, 50)],
    ),
    "dot of unit vectors": ("float f(vec3 a, vec3 b) { return dot(a, b); }", [UNIT3, UNIT3]),
    "one plus dot of unit vectors": (
        "float f(vec3 n, vec3 rd) { return 1.0 + dot(n, rd); }",
        [UNIT3, UNIT3],
    ),
    "Schlick base": (
        "float f(vec3 n, vec3 v) { return 1.0 - max(dot(n, v), 0.0); }",
        [UNIT3, UNIT3],
    ),
    "dot of normalized sums": (
        "float f(vec3 a, vec3 b) { return dot(a, normalize(a + b)); }",
        [UNIT3, Param("vec3", 0.1, 1.0)],
    ),
    "rotated unit vector": (
        ROTATE + "float f(vec3 rd, vec3 n, float a) { rd.xy *= rot(a); return 1.0 + dot(rd, n); }",
        [UNIT3, UNIT3, Param("float", -3.0, 3.0)],
    ),
    "camera ray of a look-at basis": (
        "mat3 cam(vec3 ro, vec3 ta) { vec3 cw = normalize(ta - ro);"
        " vec3 cu = normalize(cross(cw, vec3(0.0, 1.0, 0.0)));"
        " vec3 cv = normalize(cross(cu, cw)); return mat3(cu, cv, cw); }\n"
        "float f(vec3 ro, vec2 p, vec3 n) {"
        " vec3 rd = cam(ro, vec3(0.0)) * normalize(vec3(p, 1.5));"
        " return 1.0 + dot(rd, -n); }",
        [Param("vec3", 1.0, 5.0), Param("vec2", -1, 1), UNIT3],
    ),
    "smoothstep": ("float f(float x) { return smoothstep(0.2, 0.8, x); }", [Param("float", -1, 2)]),
    "fract": ("float f(float x) { return fract(x * 7.3); }", [Param("float", -100, 100)]),
    "sin remapped": ("float f(float x) { return 0.5 + 0.5 * sin(x); }", [Param("float", -9, 9)]),
    "sin times cos": ("float f(float x) { return sin(x) * cos(x); }", [Param("float", -9, 9)]),
    "sin combo": (
        "float f(float x, float t) { return sin(x * 3.0 + t) * 0.3 + cos(x * 1.7) * 0.2; }",
        [Param("float", -9, 9), Param("float", 0, 100)],
    ),
    "Hermite weight": ("float f(float t) { return t * t * (3.0 - 2.0 * t); }", [F]),
    "Henyey-Greenstein denominator": (
        "float f(float g, float c) { return 1.0 + g * g - 2.0 * g * c; }",
        [Param("float", 0.0, 0.9), Param("float", -1.0, 1.0)],
    ),
    "length of a box vector": ("float f(vec3 p) { return length(p); }", [Param("vec3", -1, 1)]),
    "mix of ramps": (
        "float f(float a, float t) { return mix(a * 2.0, 1.0 - a, t); }",
        [F, F],
    ),
    "clamped remap": (
        "float f(float x) { return clamp(x * 0.5 + 0.5, 0.0, 1.0) * 2.0 - 1.0; }",
        [Param("float", -3, 3)],
    ),
    "gamma of a lit colour": (
        "float f(float a, float d) { return pow(a * max(d, 0.0) + 0.05, 0.4545); }",
        [F, Param("float", -1, 1)],
    ),
}


def _reported(source: str, params: list[Param]) -> Interval:
    """The model's range of f's result, its parameters given by one call in mainImage."""
    args = ", ".join(p.argument(k) for k, p in enumerate(params))
    main = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        f"    fragColor = vec4(f({args}));\n}}\n"
    )
    ctx = build_context(source + "\n" + main, "t.glsl", Options(glslang=False))
    assert ctx.tree is not None, ctx.front_end_error
    fn = semantic_model(ctx).function("f", len(params))
    assert fn is not None and fn.result is not None
    return fn.result.range


def _sampled(source: str, params: list[Param]) -> tuple[float, float]:
    rng = np.random.default_rng(26)
    args = [p.sample(rng) for p in params]
    out = np.asarray(evaluate(source, "f", args, np.float64), dtype=float)
    out = out[np.isfinite(out)]
    return float(out.min()), float(out.max())


@pytest.mark.parametrize("name", CASES)
def test_reported_range_holds_the_sampled_values_and_is_plausible(name: str) -> None:
    source, params = CASES[name]
    reported = _reported(source, params)
    lo, hi = _sampled(source, params)
    slack = 1e-6 * max(1.0, abs(lo), abs(hi))
    assert reported.lo <= lo + slack and hi <= reported.hi + slack, (
        f"{name}: sampled [{lo:.4g}, {hi:.4g}] is not inside {reported.describe()}"
    )
    if reported.is_bounded:
        width = reported.hi - reported.lo
        assert width <= WIDER * max(hi - lo, 1e-3), (
            f"{name}: reported {reported.describe()} for sampled [{lo:.4g}, {hi:.4g}]"
        )
