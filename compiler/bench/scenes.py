"""Per example scene and tier: frame time, and FLIP against the same scene's reference tier; the
seed's template (`template.glsl`, the default scene written as one shader) as the baseline.

Frame time: each shader is drawn in one context per round (one round per iTime value, several
passes over them), the tiers of a scene in alternating order so that load on the machine falls
on all of them alike. A context's figure is the median of its draws, the first dropped (it may
include lazy compilation); a view's is the least over the passes (other processes only ever add
time); the frame time is the mean over the views. The time ratios are paired instead: the
median over the rounds of the ratio within each round, so that a change of machine speed
between rounds (a shared 2-core VM halves or doubles its speed for seconds at a time) cancels;
they are close to, not exactly, the quotient of the frame times. On llvmpipe a draw is CPU
time, shared with whatever else runs, and the renderer label says so.

Accuracy against the template: the template's FLIP against the reference tier says how far
apart the two are, not which one is right. So the default scene also gets a ground truth,
derived from the template by computing exactly the two terms that the tiers compute
differently there, and nothing else:

- the sun's soft shadow, as the visible fraction of a disc light of angular radius atan(1/8)
  (the light that k·h/t with k = 8 stands for, as in the shadow probes), by 32 × 32 rays
  stratified over its solid angle and intersected exactly with the sphere and the ground;
- the first hit, by the template's sphere tracing given 4096 steps instead of 128, so that no
  ray toward ground within the far distance runs out of steps at a grazing angle and shows sky;
- the environment reflection, as the specular BRDF of the key light (GGX, height-correlated
  Smith, Schlick) integrated over the gradient sky, by the quadrature of the float64 split-sum
  reference (half vectors through GGX's inverse CDF, 32 × 32 Gauss-Legendre nodes over the
  part of the lobe that reflects above the horizon), in place of the template's Schlick(N·V)
  times the sky along the mirror direction times 1 − 0.7·roughness.

The rest (camera, normals, SDF AO, specular occlusion, the fill lights, the BRDF of the
sun at the disc's centre) is the template's own code, the same as the tiers', so its error is not
what the comparison measures. Both exact terms are checked against the float64 references
(`shadow_disc_light`: mean 0.0002, max 0.02 on the ground; `dfg_split_sum`: 0.0004 for the
scene's dielectrics, 0.009 for metals at grazing angles) in tests/bench/test_bench_scenes.py.
"Measurably more accurate" means a mean FLIP against the ground truth lower by more than
MEASURABLE_FLIP.

Accuracy against the reference tier is three figures, each over the pixels of all the views
pooled: the mean FLIP, its 99th percentile (a small region gone wrong, which the mean dilutes)
and the share of outliers, pixels whose displayed luminance is under half or over twice the
reference's (a hole in a shadow, a dark ring; see images.outlier_mask for the luminance and the
floor below which near-black pixels are not compared).

The goals (bench_goals): on the default scene, balanced and fast against the template's frame
time with a mean FLIP bound and at most OUTLIER_GOAL outliers; on every other example scene,
fast at least SCENE_SPEEDUP times faster than that scene's reference tier.
"""

from __future__ import annotations

import re
import statistics
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

import numpy as np

from glint.compiler.bench.variants import is_cpu_renderer
from glint.compiler.catalog.tiers import TIERS
from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.errors import EnvironmentProblem, InputError
from glint.compiler.render import render_full
from glint.compiler.render.images import (
    channel_pictures,
    flip_error,
    flip_map,
    flip_summary,
    outlier_mask,
)
from glint.compiler.scene.model import load_scene
from glint.compiler.target.glslang import spirv_instruction_count

TEMPLATE = "template.glsl"
REFERENCE_TIER = "reference"
TEMPLATE_ROW = "template"
TEMPLATE_SCENE = "default"  # the example scene that the template renders
# The template's models as variant variants: the tiers are tuned from measurements and need not
# stay the template's; composed with these, the default scene is the template's picture.
TEMPLATE_MODELS = {
    "D": "ggx",
    "F": "schlick",
    "V": "smith_ggx_correlated",
    "diffuse": "lambert",
    "specular": "cook_torrance",
    "specocc": "power",
    "env": "gradient",
    "raymarch": "sphere_tracing",  # epsilon 0.001; 512 steps where the template has 128
    "shadow": "soft",  # 24 steps, k = 8
    "ao": "sdf5",
    "normal": "central_differences",
    "ibl": "simple_reflection",  # Schlick at N·V, times 1 − 0.7·roughness
}
DEFAULT_SIZE = (480, 270)
# The camera of the default scene orbits at 0.3 rad/s: three views 0.75 rad apart.
DEFAULT_TIMES = (0.0, 2.5, 5.0)
# Strata (rays, nodes) per side of the ground truth's two integrals: renders at 32 and at 64
# differ by at most 0.0005 mean FLIP.
TRUTH_STRATA = 32
# Ten times the ground truth's own discretisation error above, and five times the FLIP that the
# default scene's test takes for "the same picture" (0.001).
MEASURABLE_FLIP = 0.005


@dataclass
class TierMeasure:
    scene: str  # scene name
    tier: str  # "fast" | "balanced" | "reference" | "template" (default scene only)
    frame_ms: float  # median draw time (ms) at the bench size, first draw dropped; see above
    flip: float  # mean FLIP against the same scene's reference-tier render (0.0 for it)
    time_vs_reference: float  # time / the reference tier's, same scene, paired by round
    spirv: int  # SPIR-V instructions of the whole shader after spirv-opt -O
    time_vs_template: float | None = None  # default scene only: time / the template's, paired
    flip_vs_truth: float | None = None  # default scene only: mean FLIP against the ground truth
    # Against the same scene's reference-tier render, all views' pixels pooled (0.0 for it):
    flip_p99: float | None = None  # 99th percentile of the per-pixel FLIP (images.flip_summary)
    outliers: float | None = None  # share of pixels under half or over twice its luminance


@dataclass
class Goal:
    name: str
    target: str
    reached: bool
    measured: str


def template_source() -> str:
    """The seed template as one monolithic ShaderToy shader (it renders the default scene)."""
    return (resources.files("glint.compiler.bench") / TEMPLATE).read_text(encoding="utf-8")


# --- the ground truth of the default scene ---------------------------------------------------

# Same signature as the template's penumbra(); `near` is not needed by an exact test.
TRUTH_SHADOW = """\
// Ground truth: the visible fraction of a disc light of angular radius atan(1/8) around `dir`,
// by STRATA x STRATA rays uniform in solid angle, tested exactly against the unit sphere at the
// origin and the ground y = -1; occluders beyond `far` do not count.
float penumbra(vec3 origin, vec3 dir, float near, float far) {
    // min(iFrame, 0) is 0, but not to the compiler: it keeps the loops rolled (fast to compile).
    int strata = STRATA + min(iFrame, 0);
    float cosMax = cos(atan(1.0 / 8.0));
    vec3 side = abs(dir.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 t1 = normalize(cross(dir, side));
    vec3 t2 = cross(dir, t1);
    float visible = 0.0;
    for (int i = 0; i < strata; ++i) {
        for (int j = 0; j < strata; ++j) {
            float c = 1.0 - (float(i) + 0.5) / float(strata) * (1.0 - cosMax);
            float phi = 2.0 * kPi * (float(j) + 0.5) / float(strata);
            float s = sqrt(max(1.0 - c * c, 0.0));
            vec3 d = c * dir + s * (cos(phi) * t1 + sin(phi) * t2);
            // Blocked when the chord through the sphere overlaps (0, far).
            float b = dot(origin, d);
            float disc = b * b - dot(origin, origin) + 1.0;
            bool blocked = disc > 0.0 && -b + sqrt(disc) > 1e-4 && -b - sqrt(disc) < far;
            float tGround = d.y < 0.0 ? (-1.0 - origin.y) / d.y : -1.0;
            blocked = blocked || (tGround > 1e-4 && tGround < far);
            visible += blocked ? 0.0 : 1.0;
        }
    }
    return visible / float(strata * strata);
}
"""

TRUTH_ENVIRONMENT = """\
// Ground truth: the key light's specular BRDF (GGX, height-correlated Smith, Schlick) integrated
// over the gradient sky by the rule of compiler/verify/references/environment.py: half vectors
// through GGX's inverse CDF, only over the u and the azimuth arc that reflect v above the
// horizon, both by Gauss-Legendre (kNodes, kWeights on [0, 1]); a half vector weighs
// F V 4 (n.l)(v.h) / (n.h).
GAUSS_LEGENDRE
vec3 specularEnvironment(vec3 n, vec3 v, vec3 r0, float alpha) {
    float alpha2 = alpha * alpha;
    float nv = clamp(dot(n, v), 1e-4, 1.0);
    float sv = sqrt(1.0 - nv * nv);
    // The frame puts v at azimuth 0 (v clamped above the horizon, as nv is).
    vec3 side = abs(n.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 across = v - dot(n, v) * n;
    vec3 t1 = dot(across, across) > 1e-12 ? normalize(across) : normalize(cross(n, side));
    vec3 t2 = cross(n, t1);
    vec3 view = nv * n + sv * t1;
    // Past thetaH = (thetaV + pi/2) / 2 no half vector reflects v above the horizon.
    float c = cos(0.5 * (acos(nv) + 0.5 * kPi));
    float uMax = (1.0 - c * c) / (1.0 + (alpha2 - 1.0) * c * c);
    vec3 sum = vec3(0.0);
    // min(iFrame, 0) is 0, but not to the compiler: it keeps the loops rolled (fast to compile).
    int count = kNodes.length() + min(iFrame, 0);
    for (int i = 0; i < count; ++i) {
        float u = uMax * kNodes[i];
        float cosH = sqrt((1.0 - u) / (1.0 + (alpha2 - 1.0) * u));
        float sinH = sqrt(max(1.0 - cosH * cosH, 0.0));
        // n.l = 2 (v.h)(n.h) - n.v is positive for cos(phi) above this bound.
        float bound = sv * sinH > 0.0 ? (nv / (2.0 * cosH) - nv * cosH) / (sv * sinH) : -1.0;
        float phiMax = acos(clamp(bound, -1.0, 1.0));
        for (int j = 0; j < count; ++j) {
            float phi = phiMax * (2.0 * kNodes[j] - 1.0);  // over (-phiMax, phiMax)
            vec3 h = cosH * n + sinH * (cos(phi) * t1 + sin(phi) * t2);
            float vh = clamp(dot(view, h), 0.0, 1.0);  // past 1 by rounding, pow(1 - vh, 5) is NaN
            vec3 l = 2.0 * vh * h - view;
            float nl = max(dot(n, l), 0.0);
            float lambdaV = nl * sqrt(nv * nv * (1.0 - alpha2) + alpha2);
            float lambdaL = nv * sqrt(nl * nl * (1.0 - alpha2) + alpha2);
            float vis = 0.5 / max(lambdaV + lambdaL, 1e-5);
            // dphi / 2pi over an arc of 2 phiMax.
            float weight = kWeights[i] * kWeights[j] * phiMax / kPi;
            sum += skyGradient(l) * schlick(r0, vh) * (4.0 * vis * nl * vh / cosH * weight);
        }
    }
    return sum * uMax;
}
"""

_PENUMBRA = re.compile(r"^float penumbra\(.*?^}\n", re.S | re.M)
_REFLECTION = "result += schlick(r0, nv) * skyGradient(refl) * specOcc * (1.0 - 0.7 * rough);"
_EXACT_REFLECTION = "result += specularEnvironment(n, v, r0, alpha) * specOcc;"
_LIGHT_POINT = "vec3 lightPoint("
_TRACE_LOOP = "for (int k = 0; k < 128; ++k) {\n        float d = sceneDistance(origin + t * dir);"
_EXACT_TRACE_LOOP = _TRACE_LOOP.replace("128", "4096")


def truth_shadow_glsl(strata: int = TRUTH_STRATA) -> str:
    """The ground truth's penumbra(): a disc light by strata x strata rays."""
    return TRUTH_SHADOW.replace("STRATA", str(strata))


def truth_environment_glsl(strata: int = TRUTH_STRATA) -> str:
    """The ground truth's specularEnvironment(), by strata x strata Gauss-Legendre nodes; it
    calls the template's skyGradient() and schlick() and uses kPi."""
    nodes, weights = np.polynomial.legendre.leggauss(strata)

    def array(name: str, values: np.ndarray) -> str:
        return (
            f"const float {name}[{strata}] = float[{strata}]("
            + ", ".join(f"{v:.9f}" for v in values)
            + ");"
        )

    # Gauss-Legendre on [0, 1]: nodes (x + 1) / 2, weights w / 2 (they sum to 1).
    rule = array("kNodes", 0.5 * (nodes + 1.0)) + "\n" + array("kWeights", 0.5 * weights)
    return TRUTH_ENVIRONMENT.replace("GAUSS_LEGENDRE", rule)


def ground_truth_source(strata: int = TRUTH_STRATA) -> str:
    """The template with its first hit, soft shadow and environment reflection computed exactly."""
    source = template_source()
    if (
        len(_PENUMBRA.findall(source)) != 1
        or source.count(_REFLECTION) != 1
        or source.count(_TRACE_LOOP) != 1
    ):
        raise InputError(f"{TEMPLATE} changed: cannot find the terms the ground truth replaces")
    shadow, environment = truth_shadow_glsl(strata), truth_environment_glsl(strata)
    source = _PENUMBRA.sub(lambda _: shadow, source)
    source = source.replace(_REFLECTION, _EXACT_REFLECTION).replace(_TRACE_LOOP, _EXACT_TRACE_LOOP)
    return source.replace(_LIGHT_POINT, f"{environment}\n{_LIGHT_POINT}", 1)


# --- measuring ---------------------------------------------------------------------------------


def example_scenes() -> list[str]:
    """Names of the raymarched example scenes, the default (the template's scene) first.

    Mesh scenes (eight_models) are left out: the bench measures the ShaderToy tiers of one
    Image-tab shader against its reference tier, and a mesh scene is rasterized programs, one
    per material, whose `models` replace the tier's choices."""
    folder = resources.files("glint.snippets") / "scenes"
    names = sorted(Path(str(p)).stem for p in folder.iterdir() if p.name.endswith(".toml"))
    names = [name for name in names if not load_scene(_scene_path(name)).is_mesh]
    return sorted(names, key=lambda name: name != TEMPLATE_SCENE)


def _scene_path(name: str) -> Path:
    if name.endswith(".toml") or "/" in name:
        return Path(name)
    return Path(str(resources.files("glint.snippets") / "scenes" / f"{name}.toml"))


def renderer_label(renderer: str) -> str:
    """The renderer, and what its frame times are."""
    if is_cpu_renderer(renderer):
        return f"{renderer}; frame times are CPU time (software rasteriser)"
    return f"{renderer}; frame times are GPU wall time"


def _spirv(source: str, what: str) -> int:
    count = spirv_instruction_count(source)
    if count is None:
        raise EnvironmentProblem(
            f"cannot count the SPIR-V instructions of {what}: it does not compile to SPIR-V, or "
            "spirv-dis is missing (Debian: spirv-tools)"
        )
    return count


@dataclass
class _Shader:
    label: str  # tier name, or "template"
    source: str
    # the scene's pictures on its channels ([channels]), bound as glint render binds them
    channels: list[np.ndarray | None] = field(default_factory=list)
    # Per round, the median draw time (s) of its context, first draw dropped.
    medians: list[float] = field(default_factory=list)
    images: list[np.ndarray] = field(default_factory=list)  # one per iTime, from the first pass

    def frame_ms(self, views: int) -> float:
        """Mean over the views of the quietest context's median: load from other processes only
        adds time, so the least of the passes is the closest to the shader's own cost."""
        return float(np.mean([min(self.medians[v::views]) for v in range(views)])) * 1e3

    def time_vs(self, other: _Shader) -> float:
        """Median over the rounds of the time ratio within each: the two were drawn a second
        apart, so a change of machine speed between rounds cancels."""
        return statistics.median(a / b for a, b in zip(self.medians, other.medians, strict=True))


def _render_rounds(
    shaders: list[_Shader],
    size: tuple[int, int],
    repeats: int,
    times: Sequence[float],
    passes: int,
) -> str:
    """Draw every shader at every iTime, `passes` times over, one round per iTime; the order
    alternates between rounds so that drifting load falls on every shader alike."""
    renderer = ""
    for number in range(passes * len(times)):
        view = number % len(times)
        for shader in shaders if number % 2 == 0 else shaders[::-1]:
            result = render_full(
                shader.source, *size, time=times[view], repeats=repeats,
                channels=shader.channels, pictures="mipmap" if shader.channels else None,
            )  # fmt: skip
            shader.medians.append(statistics.median(result.draw_times[1:]))
            if number < len(times):
                shader.images.append(result.image)
            renderer = result.renderer
    return renderer


def _mean_flip(reference: list[np.ndarray], test: list[np.ndarray]) -> float:
    return float(np.mean([flip_error(r, t) for r, t in zip(reference, test, strict=True)]))


def _accuracy(reference: list[np.ndarray], test: list[np.ndarray]) -> tuple[float, float, float]:
    """Mean FLIP, its 99th percentile and the share of luminance outliers (images.outlier_mask)
    against the reference, over the pixels of every view pooled (all views have one size, so
    the mean and the share are also the means over the views)."""
    pairs = list(zip(reference, test, strict=True))
    mean, p99 = flip_summary([flip_map(r, t) for r, t in pairs])
    outliers = np.concatenate([outlier_mask(r, t).ravel() for r, t in pairs])
    return mean, p99, float(outliers.mean())


def _measure_scene(
    name: str,
    tiers: Sequence[str],
    size: tuple[int, int],
    repeats: int,
    times: Sequence[float],
    passes: int,
    variants: Mapping[str, Mapping[str, str]],
    with_template: bool,
    progress: Callable[[str], None] | None,
) -> tuple[list[TierMeasure], str]:
    scene = load_scene(_scene_path(name))
    if scene.is_mesh:
        raise InputError(
            f"{name}: a mesh scene; the bench measures the tiers of raymarched (ShaderToy) "
            "scenes, so leave it out of --scenes"
        )
    # The reference tier is always drawn: it is the yardstick of the others.
    measured = list(dict.fromkeys([REFERENCE_TIER, *tiers]))
    pictures = channel_pictures(scene.bound_pictures())
    shaders = [
        _Shader(
            tier,
            compose_scene(scene, tier=tier, variants=dict(variants.get(tier, {}))).text,
            pictures,
        )
        for tier in measured
    ]
    template = with_template and scene.name == TEMPLATE_SCENE
    if template:
        shaders.append(_Shader(TEMPLATE_ROW, template_source()))
    renderer = _render_rounds(shaders, size, repeats, times, passes)
    truth: list[np.ndarray] = []
    if template:
        truth = [render_full(ground_truth_source(), *size, time=t).image for t in times]

    by_label = {shader.label: shader for shader in shaders}
    reference = by_label[REFERENCE_TIER]
    baseline = by_label[TEMPLATE_ROW] if template else None
    rows = []
    for label in [*tiers, *([TEMPLATE_ROW] if template else [])]:
        shader = by_label[label]
        is_reference = shader is reference
        flip, p99, outliers = (
            (0.0, 0.0, 0.0) if is_reference else _accuracy(reference.images, shader.images)
        )
        rows.append(
            TierMeasure(
                scene=scene.name,
                tier=label,
                frame_ms=shader.frame_ms(len(times)),
                flip=flip,
                time_vs_reference=1.0 if is_reference else shader.time_vs(reference),
                spirv=_spirv(shader.source, f"{scene.name}/{label}"),
                time_vs_template=shader.time_vs(baseline) if baseline else None,
                flip_vs_truth=_mean_flip(truth, shader.images) if truth else None,
                flip_p99=p99,
                outliers=outliers,
            )
        )
        if progress is not None:
            progress(f"{scene.name}/{label}")
    return rows, renderer


def measure_scenes(
    scenes: Sequence[str] | None = None,
    tiers: Sequence[str] = TIERS,
    size: tuple[int, int] = DEFAULT_SIZE,
    repeats: int = 7,
    times: Sequence[float] = DEFAULT_TIMES,
    progress: Callable[[str], None] | None = None,
    variants: Mapping[str, Mapping[str, str]] | None = None,
    template: bool = True,
    passes: int = 3,
) -> tuple[list[TierMeasure], str]:
    """Measure each scene (example names or .toml paths; None: every example scene) at each
    tier, plus the template on the default scene; return the rows and the renderer label.

    `variants` maps a tier to slot = variant variants for it (as `--variant`); the reference
    tier is measured even when `tiers` leaves it out, as every FLIP is taken against it.
    Each shader is drawn in `passes` x len(times) contexts, `repeats` draws each, the first
    not timed; FLIP is taken on the first pass's images. `progress(label)` is called
    once per row, as "scene/tier", when the row is done.
    """
    if not times:
        raise InputError("measure_scenes needs at least one iTime value")
    rows: list[TierMeasure] = []
    renderer = ""
    for name in scenes if scenes is not None else example_scenes():
        scene_rows, renderer = _measure_scene(
            name, tiers, size, max(repeats, 2), times, max(passes, 1), variants or {},
            template, progress,
        )  # fmt: skip
        rows.extend(scene_rows)
    return rows, renderer_label(renderer)


# --- goals ----------------------------------------------------------------------------------

# Goals against the template on the default scene: (time ratio, mean FLIP) per tier, and the
# most pixels that may be luminance outliers (0.02 %: 26 pixels of a 480 x 270 view).
SPEED_GOALS = {"balanced": (0.8, 0.02), "fast": (0.5, 0.08)}
OUTLIER_GOAL = 0.0002
# On every other example scene fast is at least this much faster than the scene's reference.
SCENE_SPEEDUP = 1.5


def _row(rows: Sequence[TierMeasure], tier: str) -> TierMeasure | None:
    return next((r for r in rows if r.scene == TEMPLATE_SCENE and r.tier == tier), None)


def _speed_goal(rows: Sequence[TierMeasure], tier: str, time_ratio: float, flip: float) -> Goal:
    name = f"{tier} vs template"
    target = (
        f"{tier} at no more than {time_ratio:g}x the template's frame time, "
        f"mean FLIP <= {flip:g} against reference, at most {OUTLIER_GOAL:.2%} of pixels "
        "under half or over twice reference's luminance"
    )
    row = _row(rows, tier)
    if row is None or row.time_vs_template is None:
        return Goal(name, target, False, f"not measured (no {TEMPLATE_SCENE}/{tier} row)")
    if row.outliers is None:
        return Goal(name, target, False, "not measured (no outlier share)")
    reached = (
        row.time_vs_template <= time_ratio and row.flip <= flip and row.outliers <= OUTLIER_GOAL
    )
    measured = (
        f"{row.time_vs_template:.2f}x the template's frame time, FLIP {row.flip:.4f}, "
        f"outliers {row.outliers:.3%}"
    )
    return Goal(name, target, reached, measured)


def _accuracy_goal(rows: Sequence[TierMeasure]) -> Goal:
    name = "reference vs template"
    target = (
        f"reference's mean FLIP against the ground truth lower than the template's "
        f"by more than {MEASURABLE_FLIP:g}"
    )
    ours, theirs = _row(rows, REFERENCE_TIER), _row(rows, TEMPLATE_ROW)
    if ours is None or theirs is None or ours.flip_vs_truth is None or theirs.flip_vs_truth is None:
        return Goal(name, target, False, "not measured (needs the default scene's reference "
                    "and template rows with the ground truth)")  # fmt: skip
    reached = theirs.flip_vs_truth - ours.flip_vs_truth > MEASURABLE_FLIP
    measured = (
        f"FLIP against the ground truth: reference {ours.flip_vs_truth:.4f}, "
        f"template {theirs.flip_vs_truth:.4f}"
    )
    return Goal(name, target, reached, measured)


def template_goals(rows: Sequence[TierMeasure]) -> list[Goal]:
    """The goals against the seed template, judged on the default scene's rows."""
    return [
        *(_speed_goal(rows, tier, *bounds) for tier, bounds in SPEED_GOALS.items()),
        _accuracy_goal(rows),
    ]


def scene_goals(rows: Sequence[TierMeasure]) -> list[Goal]:
    """One goal per other scene measured with a fast row: fast at least SCENE_SPEEDUP times
    faster than the scene's reference tier (the paired time ratio)."""
    bound = 1.0 / SCENE_SPEEDUP
    goals = []
    for row in rows:
        if row.scene == TEMPLATE_SCENE or row.tier != "fast":
            continue
        ratio = row.time_vs_reference
        goals.append(
            Goal(
                f"fast vs reference, {row.scene}",
                f"fast at least {SCENE_SPEEDUP:g}x faster than reference "
                f"(<= {bound:.3f}x its frame time)",
                ratio <= bound,
                f"{ratio:.2f}x reference's frame time ({1.0 / ratio:.2f}x faster)",
            )
        )
    return goals


def bench_goals(rows: Sequence[TierMeasure]) -> list[Goal]:
    """Every goal of the bench: against the template, then fast's speed-up per other scene."""
    return [*template_goals(rows), *scene_goals(rows)]
