"""GPU probes: a snippet's entry function (or another function it defines) evaluated on the GPU
over a list of inputs.

The inputs travel as float textures (iChannel0..3, four floats per texel each, so up to sixteen
scalars per sample); one pixel evaluates one sample and writes the result into a float
framebuffer. This runs the snippet's own GLSL through the real driver, so it can be compared with
its float64 reference in `compiler/verify/references`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from glint.compiler.catalog.loader import Catalog, Snippet, load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.compose.linking.standalone import SCENE_STUB, standalone_source
from glint.compiler.errors import InputError
from glint.compiler.glsl.symbols import FunctionDef, analyze
from glint.compiler.render import render, render_full
from glint.compiler.target import shadertoy
from glint.compiler.target.shadertoy import UNIFORM_NAMES

PROBE_PRELUDE = (
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "uniform vec3 iResolution;\n"
    "uniform float iTime;\n"  # read by camera.orbit; 0 in a probe
    "uniform vec4 iMouse;\n"  # read by camera.orbit; 0 in a probe
    "uniform highp sampler2D iChannel0;\n"
    "uniform highp sampler2D iChannel1;\n"
    "uniform highp sampler2D iChannel2;\n"
    "uniform highp sampler2D iChannel3;\n"
)
# Struct arguments are passed field by field, in declaration order (see snippets/core).
STRUCT_FIELDS: dict[str, tuple[str, ...]] = {
    "Dots": ("NoL", "NoV", "NoH", "VoH", "LoV", "NoLsigned")
}
# A Surface is built from two inputs, its perceptual roughness and N·V; the rest is fixed: a
# white diffuse albedo, the dielectric f0, N = V = +z at the origin, a = roughness² and the
# diffuse roughness equal to the roughness.
SURFACE_INPUTS = ("roughness", "NoV")
SURFACE_FIXED = "vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(1.0), vec3(0.04)"
_SIZES = {"float": 1, "vec2": 2, "vec3": 3, "vec4": 4}
# How each result type fills the framebuffer's vec4; the unused channels are padding.
_RESULTS = {
    "float": "vec4({}, 0.0, 0.0, 1.0)",
    "vec2": "vec4({}, 0.0, 1.0)",
    "vec3": "vec4({}, 1.0)",
    "vec4": "{}",
}
_CHANNELS = 4
_SLOTS_PER_SAMPLE = 4 * _CHANNELS
_ROW = 256  # texels per row of the input textures and the framebuffer
# Evaluations per timed pass: every variant is timed over the same 256 x 256 grid, its samples
# repeated to fill it, so that passes of different variants do the same amount of work.
TIMED_PIXELS = _ROW * _ROW
# Calls per pixel in a timed pass: with one, fetching the inputs and writing the result cost more
# than a short function, and the timing noise hides it; a loop of calls resolves it.
TIMED_CALLS = 32
# Each call of the loop sees its inputs scaled by 1 - k·JITTER (call k): a different value, so the
# compiler cannot hoist the call out of the loop, yet inside any domain that contains 0.
JITTER = "1e-6"


@dataclass(frozen=True)
class Argument:
    """One scalar input of a probe: `name` is a parameter, or `param.field` for a struct."""

    name: str
    glsl: str  # how the probe shader reads it, e.g. "in0.x"


def snippet_function(snippet: Snippet, name: str) -> FunctionDef:
    """The function `name` as defined in the snippet's own body. Only its own: a function it
    gets from a required snippet belongs to that snippet and is probed there."""
    functions = analyze(snippet.body, snippet.relpath, provided=UNIFORM_NAMES).functions
    found = next((f for f in functions if f.name == name), None)
    if found is None:
        defined = ", ".join(f.name for f in functions) or "none"
        raise InputError(
            f"{snippet.id}: no function {name} defined in the snippet to probe "
            f"(it defines: {defined})"
        )
    return found


def entry_function(snippet: Snippet) -> FunctionDef:
    """The function a probe calls: the slot's entry; for a library snippet with a domain (a
    light's falloff), the function it provides first."""
    slot = SLOTS[snippet.slot]
    if slot.entry is None and snippet.domain and snippet.provides:
        return snippet_function(snippet, snippet.provides[0])
    if slot.entry is None:
        raise InputError(f"{snippet.id}: slot {slot.name} has no entry function to probe")
    return snippet_function(snippet, slot.entry)


def probe_inputs(function: FunctionDef, out_params: bool = False) -> tuple[list[str], str]:
    """The scalar input names a probe of `function` takes, and the GLSL call that uses them.
    An out parameter is refused unless `out_params`, where it becomes the probe's local
    `out_<name>` (see `probe_shader`)."""
    names: list[str] = []
    args: list[str] = []

    def scalar(name: str) -> str:
        index = len(names)
        names.append(name)
        return f"in{index // 4}.{'xyzw'[index % 4]}"

    for param in function.params:
        if "out" in param.qualifier.split():
            if not out_params:
                raise InputError(f"{function.name}: cannot probe an out parameter ({param.name})")
            args.append(f"out_{param.name}")
        elif param.type in _SIZES:
            size = _SIZES[param.type]
            if size == 1:
                args.append(scalar(param.name))
            else:
                parts = [scalar(f"{param.name}{i}") for i in range(size)]
                args.append(f"{param.type}({', '.join(parts)})")
        elif param.type == "int":  # an enumeration or a count, sent as a float
            args.append(f"int({scalar(param.name)} + 0.5)")
        elif param.type in STRUCT_FIELDS:
            fields = [scalar(f"{param.name}.{f}") for f in STRUCT_FIELDS[param.type]]
            args.append(f"{param.type}({', '.join(fields)})")
        elif param.type == "Surface":
            rough, nov = (scalar(f"{param.name}.{f}") for f in SURFACE_INPUTS)
            args.append(f"Surface({SURFACE_FIXED}, {rough}, {rough} * {rough}, {nov}, {rough})")
        else:
            raise InputError(f"{function.name}: cannot probe a parameter of type {param.type}")
    if len(names) > _SLOTS_PER_SAMPLE:
        raise InputError(
            f"{function.name}: {len(names)} scalar inputs, a probe takes at most "
            f"{_SLOTS_PER_SAMPLE}"
        )
    return names, f"{function.name}({', '.join(args)})"


def _fetches(channels: int = _CHANNELS, name: str = "in") -> str:
    return "    ivec2 texel = ivec2(fragCoord);\n" + "".join(
        f"    vec4 {name}{c} = texelFetch(iChannel{c}, texel, 0);\n" for c in range(channels)
    )


def _main_image(body: str) -> str:
    return f"void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}}}\n"


def _main(statements: str, result: str, calls: int, channels: int = _CHANNELS) -> str:
    """mainImage of a probe: the inputs fetched, then one call written out, or (`calls` > 1,
    for timing) the sum of `calls` calls, each on inputs a little apart (JITTER)."""
    if calls == 1:
        body = f"{_fetches(channels)}{statements}    fragColor = {result};\n"
    else:
        fetched = _fetches(channels, "base")
        jittered = "".join(f"        vec4 in{c} = base{c} * scale;\n" for c in range(channels))
        inner = "".join(f"    {line}\n" for line in statements.splitlines())
        body = (
            f"{fetched}    vec4 total = vec4(0.0);\n"
            f"    for (int k = 0; k < {calls}; k++) {{\n"
            f"        float scale = 1.0 - float(k) * {JITTER};\n"
            f"{jittered}{inner}        total += {result};\n"
            "    }\n"
            "    fragColor = total;\n"
        )
    return _main_image(body)


def _outputs(function: FunctionDef, call: str) -> tuple[str, str, str]:
    """For a void function with out parameters (cameraRay): the statements that declare them
    and make the call, the result and its type. The result is their sum, so that no output is
    optimised away: it serves timing and static cost, its value means little."""
    outs = [p for p in function.params if "out" in p.qualifier.split()]
    if function.return_type != "void" or len({p.type for p in outs}) != 1:
        raise InputError(f"{function.name}: out parameters of one type, and no result, expected")
    declare = "".join(f"    {p.type} out_{p.name};\n" for p in outs)
    return f"{declare}    {call};\n", " + ".join(f"out_{p.name}" for p in outs), outs[0].type


def probe_shader(
    snippet: Snippet,
    catalog: Catalog,
    scene_stub: str = SCENE_STUB,
    function: str | None = None,
    out_params: bool = False,
    calls: int = 1,
) -> tuple[str, list[str], int]:
    """The probe's source, its scalar input names and the width of its result (1 to 4).
    `scene_stub` defines `map` (and `materialAt`) for snippets that query the scene; `function`
    names a function of the snippet to probe instead of its slot's entry; `out_params` allows a
    void function with out parameters (see `_outputs`); `calls` > 1 makes a timing probe whose
    result is a sum of that many calls (see `_main`)."""
    probed = entry_function(snippet) if function is None else snippet_function(snippet, function)
    names, call = probe_inputs(probed, out_params)
    statements, value, result_type = "", call, probed.return_type
    if out_params and any("out" in p.qualifier.split() for p in probed.params):
        statements, value, result_type = _outputs(probed, call)
    if result_type not in _RESULTS:
        raise InputError(f"{probed.name}: cannot probe a {result_type} result")
    result, width = _RESULTS[result_type].format(value), _SIZES[result_type]
    main = _main(statements, result, calls)
    # A complete shader with its own prelude: ShaderToy's declares iChannel0..3 without a
    # precision, so they default to lowp, and Mesa then returns texel values at half precision.
    code = standalone_source(snippet, catalog, main, scene_stub)
    return PROBE_PRELUDE + code + shadertoy.EPILOGUE, names, width


def run_probe(
    snippet_id: str,
    inputs: dict[str, np.ndarray],
    catalog: Catalog | None = None,
    scene_stub: str = SCENE_STUB,
    function: str | None = None,
) -> np.ndarray:
    """Evaluate the snippet's entry on the GPU for every sample: `inputs` maps each scalar input
    name (see `probe_inputs`) to an array of shape (N,). Returns float32 (N,) for a float result,
    else (N, width) for a vec2, vec3 or vec4. `scene_stub` is GLSL defining `map(vec3)` and
    `materialAt(vec3)` for snippets that need the scene (AO, shadows, normals); by default a unit
    sphere above the plane y = -1. `function` probes that function of the snippet (defined in its
    own body, e.g. a helper such as envBRDFApprox) instead of the slot's entry."""
    catalog = catalog or load_catalog()
    source, names, width = probe_shader(catalog.get(snippet_id), catalog, scene_stub, function)
    return _samples(source, snippet_id, names, inputs, width)


def _samples(
    source: str, snippet_id: str, names: list[str], inputs: dict[str, np.ndarray], width: int
) -> np.ndarray:
    """A probe's values: one pixel per sample, its inputs packed into the channels."""
    count = _sample_count(snippet_id, names, inputs)
    channels, rows, cols = _pack(names, inputs, count, min(count, _ROW))
    return _unpack(render(source, cols, rows, channels=channels), count, width)


def run_statements(
    snippet_id: str,
    statements: str,
    names: list[str],
    inputs: dict[str, np.ndarray],
    width: int,
    catalog: Catalog | None = None,
) -> np.ndarray:
    """The snippet, with everything it needs, under GLSL `statements` of the caller's that set
    fragColor from the scalar inputs `names`, read in order as in0.x, in0.y, ... in3.w (a case
    the entry's own probe cannot build, such as a Surface from its own N and V). Returns the
    first `width` channels per sample, as run_probe does."""
    catalog = catalog or load_catalog()
    main = _main_image(_fetches() + statements)
    code = standalone_source(catalog.get(snippet_id), catalog, main, SCENE_STUB)
    return _samples(PROBE_PRELUDE + code + shadertoy.EPILOGUE, snippet_id, names, inputs, width)


@dataclass(frozen=True)
class TimedProbe:
    """A probe pass drawn several times: its values and how long each draw took."""

    values: np.ndarray  # as `run_probe` returns them, one per sample given
    draw_times: list[float]  # seconds per draw, the first (lazy compilation on Mesa) included
    evaluations: int  # calls of the function per draw (pixels times calls per pixel)
    renderer: str  # GL_RENDERER and version of the driver that drew it

    def median_draw(self) -> float:
        """Median seconds of the draws after the first (that one may compile the shader)."""
        times = self.draw_times[1:] or self.draw_times
        return float(np.median(times))


def run_probe_timed(
    snippet_id: str,
    inputs: dict[str, np.ndarray],
    catalog: Catalog | None = None,
    scene_stub: str = SCENE_STUB,
    function: str | None = None,
    repeats: int = 7,
    pixels: int = TIMED_PIXELS,
    out_params: bool = False,
    calls: int = 1,
) -> TimedProbe:
    """`run_probe` drawn `repeats` times in one context over a grid of at least `pixels`
    pixels: the samples are repeated, in order, to fill it. `out_params` lets a void entry
    with out parameters (cameraRay) be timed; its values are then the sum of its outputs.
    With `calls` > 1 each pixel calls the function that many times (see `_main`), and the
    values come from a pass of one call each."""
    catalog = catalog or load_catalog()
    snippet = catalog.get(snippet_id)
    source, names, width = probe_shader(snippet, catalog, scene_stub, function, out_params, calls)
    count = _sample_count(snippet_id, names, inputs)
    channels, rows, cols = _pack(names, inputs, max(count, pixels), _ROW)
    frame = render_full(source, cols, rows, channels=channels, repeats=repeats)
    if calls == 1:
        values = _unpack(frame.image, count, width)
    else:  # the loop's sum means little: the values are one call's, one pixel per sample
        single = probe_shader(snippet, catalog, scene_stub, function, out_params)[0]
        values = _samples(single, snippet_id, names, inputs, width)
    return TimedProbe(values, frame.draw_times, rows * cols * calls, frame.renderer)


def probe_channels(names: list[str]) -> int:
    """How many input textures a probe with these scalar inputs reads (four scalars each)."""
    return max(1, math.ceil(len(names) / 4))


def empty_probe_shader(channels: int, calls: int = 1) -> str:
    """A probe that evaluates nothing: it fetches the first `channels` input texels, as a probe
    with that many inputs does, and writes their sum, so that no fetch is optimised away; with
    `calls` > 1, the same loop as a timing probe's, summing the jittered inputs instead."""
    fetched = " + ".join(f"in{c}" for c in range(channels)) or "vec4(0.0)"
    return PROBE_PRELUDE + _main("", fetched, calls, channels) + shadertoy.EPILOGUE


def run_empty_probe(
    channels: int, repeats: int = 7, pixels: int = TIMED_PIXELS, calls: int = 1
) -> TimedProbe:
    """The timed pass of `empty_probe_shader` over the same grid as `run_probe_timed`: what a
    probe costs before its function does anything."""
    names = [f"x{i}" for i in range(4 * channels)]
    inputs = {name: np.linspace(0.0, 1.0, pixels) for name in names}
    data, rows, cols = _pack(names, inputs, pixels, _ROW)
    shader = empty_probe_shader(channels, calls)
    frame = render_full(shader, cols, rows, channels=data, repeats=repeats)
    values = _unpack(frame.image, pixels, 4)
    return TimedProbe(values, frame.draw_times, rows * cols * calls, frame.renderer)


def _sample_count(snippet_id: str, names: list[str], inputs: dict[str, np.ndarray]) -> int:
    missing = [n for n in names if n not in inputs]
    if missing:
        raise InputError(f"{snippet_id}: probe inputs missing: {', '.join(missing)}")
    return len(np.asarray(inputs[names[0]]))


def _pack(
    names: list[str], inputs: dict[str, np.ndarray], pixels: int, cols: int
) -> tuple[list[np.ndarray], int, int]:
    """The input textures for `pixels` texels, `cols` per row: sample i in texel i, the samples
    repeated in order where there are fewer than texels. Returns them, the rows and the cols."""
    rows = max(1, math.ceil(pixels / cols))
    data = np.zeros((rows * cols, _SLOTS_PER_SAMPLE), dtype=np.float32)
    for index, name in enumerate(names):
        data[:, index] = np.resize(np.asarray(inputs[name], dtype=np.float32), rows * cols)
    channels = [data[:, 4 * c : 4 * c + 4].reshape(rows, cols, 4) for c in range(_CHANNELS)]
    return channels, rows, cols


def _unpack(image: np.ndarray, count: int, width: int) -> np.ndarray:
    # Rendered rows come top-first; texel row 0 (the first samples) is the bottom row.
    values = image[::-1].reshape(-1, 4)[:count]
    return values[:, 0] if width == 1 else values[:, :width]
