"""GPU probes: a snippet's entry function (or another function it defines) evaluated on the GPU
over a list of inputs.

The inputs travel as float textures (iChannel0..3, four floats per texel each, so up to sixteen
scalars per sample); one pixel evaluates one sample and writes the result into a float
framebuffer. This runs the snippet's own GLSL through the real driver, so it can be compared with
its float64 reference in `compiler/references`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import shadertoy
from .catalog import Catalog, Snippet, load_catalog
from .errors import InputError
from .glsl.symbols import FunctionDef, analyze
from .render import render
from .slots import SLOTS
from .standalone import SCENE_STUB, standalone_source

PROBE_PRELUDE = (
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "uniform vec3 iResolution;\n"
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


@dataclass(frozen=True)
class Argument:
    """One scalar input of a probe: `name` is a parameter, or `param.field` for a struct."""

    name: str
    glsl: str  # how the probe shader reads it, e.g. "in0.x"


def snippet_function(snippet: Snippet, name: str) -> FunctionDef:
    """The function `name` as defined in the snippet's own body. Only its own: a function it
    gets from a required snippet belongs to that snippet and is probed there."""
    functions = analyze(snippet.body, snippet.relpath).functions
    found = next((f for f in functions if f.name == name), None)
    if found is None:
        defined = ", ".join(f.name for f in functions) or "none"
        raise InputError(
            f"{snippet.id}: no function {name} defined in the snippet to probe "
            f"(it defines: {defined})"
        )
    return found


def entry_function(snippet: Snippet) -> FunctionDef:
    slot = SLOTS[snippet.slot]
    if slot.entry is None:
        raise InputError(f"{snippet.id}: slot {slot.name} has no entry function to probe")
    return snippet_function(snippet, slot.entry)


def probe_inputs(function: FunctionDef) -> tuple[list[str], str]:
    """The scalar input names a probe of `function` takes, and the GLSL call that uses them."""
    names: list[str] = []
    args: list[str] = []

    def scalar(name: str) -> str:
        index = len(names)
        names.append(name)
        return f"in{index // 4}.{'xyzw'[index % 4]}"

    for param in function.params:
        if "out" in param.qualifier.split():
            raise InputError(f"{function.name}: cannot probe an out parameter ({param.name})")
        if param.type in _SIZES:
            size = _SIZES[param.type]
            if size == 1:
                args.append(scalar(param.name))
            else:
                parts = [scalar(f"{param.name}{i}") for i in range(size)]
                args.append(f"{param.type}({', '.join(parts)})")
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


def probe_shader(
    snippet: Snippet,
    catalog: Catalog,
    scene_stub: str = SCENE_STUB,
    function: str | None = None,
) -> tuple[str, list[str], int]:
    """The probe's source, its scalar input names and the width of its result (1 to 4).
    `scene_stub` defines `map` (and `materialAt`) for snippets that query the scene; `function`
    names a function of the snippet to probe instead of its slot's entry."""
    probed = entry_function(snippet) if function is None else snippet_function(snippet, function)
    names, call = probe_inputs(probed)
    if probed.return_type not in _RESULTS:
        raise InputError(f"{probed.name}: cannot probe a {probed.return_type} result")
    result, width = _RESULTS[probed.return_type].format(call), _SIZES[probed.return_type]
    main = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    ivec2 texel = ivec2(fragCoord);\n"
        "    vec4 in0 = texelFetch(iChannel0, texel, 0);\n"
        "    vec4 in1 = texelFetch(iChannel1, texel, 0);\n"
        "    vec4 in2 = texelFetch(iChannel2, texel, 0);\n"
        "    vec4 in3 = texelFetch(iChannel3, texel, 0);\n"
        f"    fragColor = {result};\n"
        "}\n"
    )
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
    snippet = catalog.get(snippet_id)
    source, names, width = probe_shader(snippet, catalog, scene_stub, function)
    missing = [n for n in names if n not in inputs]
    if missing:
        raise InputError(f"{snippet_id}: probe inputs missing: {', '.join(missing)}")
    count = len(np.asarray(inputs[names[0]]))
    rows = max(1, math.ceil(count / _ROW))
    cols = min(count, _ROW)
    data = np.zeros((rows * cols, _SLOTS_PER_SAMPLE), dtype=np.float32)
    for index, name in enumerate(names):
        data[:count, index] = np.asarray(inputs[name], dtype=np.float32)
    channels = [data[:, 4 * c : 4 * c + 4].reshape(rows, cols, 4) for c in range(_CHANNELS)]
    image = render(source, cols, rows, channels=channels)
    # Rendered rows come top-first; texel row 0 (the first samples) is the bottom row.
    values = image[::-1].reshape(rows * cols, 4)[:count]
    return values[:, 0] if width == 1 else values[:, :width]
