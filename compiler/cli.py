"""The `glint` command line: compose, validate, render and catalog (and the commands other parts
of glint register, such as `lint`).

Exit codes: 0 success, 1 a problem with the input (scene, shader), 2 usage or environment.
Every failure is one message on stderr; no traceback reaches the user.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from importlib.metadata import entry_points
from importlib.metadata import version as package_version
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from glint.compiler.catalog.tiers import TIERS
from glint.compiler.errors import EnvironmentProblem, GlintError, InputError, UsageError, printable
from glint.compiler.files import read_text_file
from glint.compiler.render import limits
from glint.compiler.target import shadertoy
from glint.compiler.target.cross import LANGS
from glint.compiler.target.mesh import MESH_TARGETS
from glint.compiler.target.shadertoy import TARGETS, channel_binding
from glint.compiler.target.shadertoy_project import is_project
from glint.compiler.target.sourcemap import with_includes

if TYPE_CHECKING:
    from glint.compiler.api import Shader

PROG = "glint"
T = TypeVar("T")


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    handler: Callable[[argparse.Namespace], int] = args.handler
    try:
        return handler(args)
    except GlintError as exc:
        print(f"{PROG}: {printable(exc.message, keep_line_feeds=True)}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # The reader went away (`glint catalog | head`): stop quietly, as Unix tools do, and
        # point stdout at /dev/null so that the interpreter's final flush does not fail again.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:  # a bug of glint's own: say so in one line, never a traceback
        print(
            f"{PROG}: internal error: {type(exc).__name__}: {exc}; please report it",
            file=sys.stderr,
        )
        return 2


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=PROG,
        description="Compose, validate, render and lint ShaderToy lighting shaders.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {_version()}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    compose = sub.add_parser("compose", help="compose a scene into one shader")
    compose.add_argument("scene", nargs="?", help="scene TOML file (default: the embedded scene)")
    compose.add_argument(
        "-o", "--output", help="write the shader to this file (default, or -: standard output)"
    )
    compose.add_argument(
        "--explain",
        action="store_true",
        help="print, for each slot, whether it is in and why and which variant fills it and why "
        "(the shader goes to -o if given)",
    )
    _add_target(compose, TARGETS + LANGS + MESH_TARGETS)
    compose.add_argument(
        "--params-as-uniforms",
        action="store_true",
        help="webgl2 only: each parameter with a range becomes a uniform a page can set, listed "
        "in a /* glint-params [JSON] */ block (name, type, default, min, max)",
    )
    compose.add_argument(
        "--split",
        choices=["common"],
        help="common: write the lighting library for ShaderToy's Common tab to "
        "OUTPUT.common.glsl and a short Image tab that uses it to OUTPUT (needs -o)",
    )
    compose.add_argument(
        "--format",
        choices=["glsl", "shadertoy-json"],
        default="glsl",
        help="shadertoy-json: write ShaderToy's JSON (an Image pass, with --split common a "
        "Common pass too, and the scene's pictures as its texture inputs), which ShaderToy's "
        "import, glint render and wgpu-shadertoy's from_json read",
    )
    compose.add_argument(
        "--no-validate",
        action="store_true",
        help="write the shader without checking it first (by default a shader that does not "
        "compile with glslangValidator is an error, at the scene's file and line, and nothing "
        "is written; a [geometry] field is sampled for a slope over its lipschitz and for "
        "material ids nothing maps, each a warning)",
    )
    _add_quality(compose)
    compose.set_defaults(handler=cmd_compose)

    validate = sub.add_parser("validate", help="check a shader with glslangValidator")
    validate.add_argument(
        "file",
        help="ShaderToy Image-tab shader (.glsl), or a ShaderToy project (its JSON, or a folder "
        "of tabs): every pass with its Common tab and channels",
    )
    _add_target(validate, TARGETS)
    validate.add_argument(
        "--common",
        metavar="FILE",
        help="ShaderToy's Common tab, compiled in front of the file (default: NAME.common.glsl "
        "beside NAME.glsl when there is one); a NAME.common.glsl file is checked as a Common tab",
    )
    validate.add_argument(
        "--channel",
        action="append",
        type=_channel,
        default=[],
        metavar="N=KIND",
        help="what iChannelN is bound to: 2d (the default), cube or 3d; e.g. --channel 0=cube",
    )
    validate.set_defaults(handler=cmd_validate)

    render = sub.add_parser("render", help="render a shader or a scene to a PNG")
    render.add_argument(
        "input",
        help="shader file, scene .toml to compose first, or a ShaderToy project (its JSON export, "
        "or a folder of tabs)",
    )
    render.add_argument(
        "-o", "--output", required=True, help="PNG file to write (-: standard output)"
    )
    render.add_argument(
        "--size",
        default="640x360",
        type=_render_size,
        help=f"WxH, each 1..{limits.MAX_SIDE}, within the memory available (default 640x360)",
    )
    render.add_argument("--time", type=_uniform_float, default=0.0, help="iTime in seconds")
    render.add_argument("--frame", type=_frame, default=0, help=f"iFrame, 0..{limits.MAX_FRAME}")
    render.add_argument(
        "--frames",
        type=int,
        default=1,
        help="a ShaderToy project (its JSON, or a folder of tabs): frames to run, 1/60 s apart "
        "from --time, its buffers feeding the next frame; the last frame's Image is written",
    )
    render.add_argument("--mouse", type=_mouse, default=(0.0, 0.0, 0.0, 0.0), help="x,y,z,w")
    render.add_argument(
        "--timeout",
        type=_timeout,
        default=60.0,
        help=f"seconds before giving up (default 60, at most {limits.MAX_TIMEOUT_S:g})",
    )
    render.add_argument(
        "--channel",
        type=_picture_channel,
        action="append",
        default=[],
        metavar="N=PICTURE",
        help="bind a picture file to iChannelN (0-3) as ShaderToy binds one (repeatable), "
        "e.g. --channel 0=stone.png for a material's albedo_texture = 0",
    )
    render.add_argument("--json", action="store_true", help="print the report as JSON")
    _add_quality(render)
    render.set_defaults(handler=cmd_render)

    catalog = sub.add_parser("catalog", help="list the snippet catalog, or show one snippet")
    catalog.add_argument("--json", action="store_true", help="one JSON object per snippet")
    catalog.set_defaults(handler=cmd_catalog)
    actions = catalog.add_subparsers(dest="action", metavar="ACTION")
    show = actions.add_parser(
        "show", help="print a snippet with its dependencies as one pasteable GLSL block"
    )
    show.add_argument("id", metavar="ID", help="snippet id, e.g. D.ggx (see `glint catalog`)")
    show.add_argument(
        "--lang",
        choices=("glsl", *LANGS),
        default="glsl",
        help="glsl (default); hlsl or msl: converted through SPIR-V (needs spirv-cross)",
    )
    show.set_defaults(handler=cmd_catalog_show)
    bench = sub.add_parser(
        "bench",
        help="measure each variant's error and cost and each tier's FLIP and frame time",
    )
    bench.add_argument("--out", default="bench", help="folder for bench.json, bench.md, charts")
    bench.add_argument(
        "--update",
        action="store_true",
        help="also write the variants' measurements into the catalog (snippets/measurements.json)",
    )
    bench.add_argument("--slots", type=_names, help="only these slots' variants, e.g. D,F,shadow")
    bench.add_argument("--scenes", type=_names, help="only these example scenes (or .toml files)")
    bench.add_argument("--size", default="480x270", type=_size, help="scene render size WxH")
    bench.add_argument("--repeats", type=int, default=7, help="timed draws per measurement")
    bench.add_argument("--no-variants", action="store_true", help="skip the per-variant part")
    bench.add_argument("--no-scenes", action="store_true", help="skip the scenes and tiers")
    bench.add_argument("--no-charts", action="store_true", help="write no PNG charts")
    bench.set_defaults(handler=cmd_bench)
    _add_plugin_commands(sub)
    return parser


def _add_plugin_commands(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    """Commands other parts of glint register under the `glint.commands` entry point (the
    linter's `lint` and `rule`), found by name so that the compiler never imports them."""
    for entry in entry_points(group="glint.commands"):
        entry.load()(sub)


def _add_target(parser: argparse.ArgumentParser, choices: tuple[str, ...]) -> None:
    converted = (
        "; hlsl, msl: the shadertoy shader as an HLSL pixel shader / Metal fragment function, "
        "converted through SPIR-V (needs spirv-cross)"
        if LANGS[0] in choices
        else ""
    )
    mesh = (
        "; mesh-webgl2, mesh-desktop: a mesh scene's vertex and fragment shaders (-o BASE "
        "writes BASE.vert, BASE.frag, BASE.background.frag)"
        if MESH_TARGETS[0] in choices
        else ""
    )
    parser.add_argument(
        "--target",
        choices=choices,
        default="shadertoy",
        help="shadertoy: the Image tab (default); webgl2: ES 3.00; desktop: #version 330"
        + converted
        + mesh,
    )


def _add_quality(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--tier", choices=TIERS, help="quality tier")
    parser.add_argument(
        "--budget",
        type=_budget,
        metavar="NS",
        help="cost budget per pixel in ns, as measured by `glint bench --update`: the most "
        "accurate variants within it replace the tier's",
    )
    parser.add_argument(
        "--variant",
        action="append",
        default=[],
        metavar="SLOT=VARIANT",
        help="choose a variant for a slot (repeatable), e.g. --variant shadow=hard",
    )


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WxH such as 640x360, got {text!r}") from None
    if not (1 <= w <= limits.MAX_SIDE and 1 <= h <= limits.MAX_SIDE):
        raise argparse.ArgumentTypeError(
            f"width and height must be 1..{limits.MAX_SIDE}, got {text!r}"
        )
    return w, h


def _render_size(text: str) -> tuple[int, int]:
    """WxH, and no larger than what the machine can render (limits.size_problem)."""
    width, height = _size(text)
    problem = limits.size_problem(width, height)
    if problem is not None:
        raise argparse.ArgumentTypeError(problem)
    return width, height


def _number(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None


def _whole(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None


def _checked(
    convert: Callable[[str], T], problem_of: Callable[[T], str | None]
) -> Callable[[str], T]:
    """An argparse type: the text converted, and refused with what `problem_of` finds wrong."""

    def parse(text: str) -> T:
        value = convert(text)
        problem = problem_of(value)
        if problem is not None:
            raise argparse.ArgumentTypeError(f"{problem}, got {text!r}")
        return value

    return parse


_timeout = _checked(_number, limits.timeout_problem)
_uniform_float = _checked(_number, limits.float32_problem)
_frame = _checked(_whole, limits.frame_problem)


def _names(text: str) -> list[str]:
    names = [n.strip() for n in text.split(",") if n.strip()]
    if not names:
        raise argparse.ArgumentTypeError(f"expected comma-separated names, got {text!r}")
    return names


def _budget(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not value > 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"expected a positive number of ns, got {text!r}")
    return value


def _mouse(text: str) -> tuple[float, float, float, float]:
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        values = ()
    if len(values) != 4:
        raise argparse.ArgumentTypeError(f"expected four numbers x,y,z,w, got {text!r}")
    if any(limits.float32_problem(v) for v in values):
        raise argparse.ArgumentTypeError(
            f"each of x,y,z,w {limits.float32_problem(float('inf'))}, got {text!r}"
        )
    return values  # type: ignore[return-value]


def _variants(pairs: list[str]) -> dict[str, str]:
    result = {}
    for pair in pairs:
        slot, sep, variant = pair.partition("=")
        if not sep or not slot or not variant:
            raise UsageError(f"--variant expects SLOT=VARIANT, got {pair!r}")
        result[slot.strip()] = variant.strip()
    return result


def _version() -> str:
    # the installed distribution's version, as compose.pipeline.glint_version reads it; not
    # imported from there, which would load the whole composer for every command
    return package_version("glint")


def cmd_compose(args: argparse.Namespace) -> int:
    import glint

    if args.target in MESH_TARGETS:
        return _compose_mesh(args)

    shader = glint.compose(
        Path(args.scene) if args.scene is not None else None,
        target=args.target,
        tier=args.tier,
        variants=_variants(args.variant),
        budget=args.budget,
        params_as_uniforms=args.params_as_uniforms,
    )
    if not args.no_validate and args.target not in LANGS:
        _refuse_invalid(shader.validate)
    if not args.no_validate and shader.scene.geometry is not None:
        _check_field(shader)
    to_stdout = args.output == "-"
    if args.explain:  # beside a shader on standard output, on stderr
        (sys.stderr if to_stdout else sys.stdout).write(shader.explain())
    if args.format == "shadertoy-json":
        return _write_json(shader, args.split == "common", args.output)
    if args.split:
        return _write_split(shader, args.output)
    if args.output and not to_stdout:
        shader.save(args.output)
        print(
            f"wrote {args.output}: {args.target} shader, {len(shader.snippets)} snippets, "
            f"tier {shader.tier}",
            file=sys.stderr,
        )
    elif to_stdout or not args.explain:
        sys.stdout.write(shader.text)
    return 0


def _compose_mesh(args: argparse.Namespace) -> int:
    """A mesh scene's programs: several files, so -o names their common stem."""
    import glint

    if args.split or args.params_as_uniforms or args.budget is not None:
        used = (
            "--split"
            if args.split
            else "--params-as-uniforms"
            if args.params_as_uniforms
            else "--budget"
        )
        raise UsageError(f"{used} is not available for --target {args.target}")
    shader = glint.compose_mesh(
        Path(args.scene) if args.scene is not None else None,
        target=args.target,
        tier=args.tier,
        variants=_variants(args.variant),
    )
    if args.explain:
        sys.stdout.write(shader.explain())
    if args.output == "-":
        raise UsageError(f"--target {args.target} writes several files: give -o BASE, not -")
    if not args.no_validate:
        _refuse_invalid(shader.validate)
    if not args.output:
        if args.explain:
            return 0
        raise UsageError(
            f"--target {args.target} writes a vertex and a fragment shader per material: give "
            "-o BASE (BASE.vert, BASE.frag, BASE.background.frag; BASE.MATERIAL.vert/.frag "
            "for several materials)"
        )
    written = shader.save(args.output)
    print(f"wrote {', '.join(str(p) for p in written)}: {args.target}", file=sys.stderr)
    return 0


def _refuse_invalid(validate: Callable[[], list[Any]]) -> None:
    """Compile what compose is about to write: a shader that does not compile is never written
    (a GLSL error in the scene's own file would otherwise show only when pasted). Its errors go
    to stderr at the scene's file and line, and compose exits 1. Without glslangValidator, one
    line says the shader was not checked."""
    try:
        diagnostics = validate()
    except EnvironmentProblem as problem:
        print(f"glint: not validated: {problem}; --no-validate skips the check", file=sys.stderr)
        return
    errors = [d for d in diagnostics if d.severity == "error"]
    if not errors:
        return
    for diagnostic in errors:
        print(diagnostic, file=sys.stderr)
    count = f"{len(errors)} error{'s' if len(errors) > 1 else ''}"
    raise InputError(
        f"the composed shader does not compile ({count} above, at their source lines); "
        "nothing was written. Fix the scene's file, or pass --no-validate to write it anyway"
    )


def _check_field(shader: Shader) -> None:
    """Warn of what a [geometry] field promises and does not keep (compiler/verify/
    field_checks.py): it samples the field on the GPU, so without one it says it did not."""
    from glint.compiler.verify.field_checks import field_warnings

    text = shader.text if shader.target == "shadertoy" else shader.retarget("shadertoy").text
    try:
        warnings = field_warnings(shader.scene, text)
    except (EnvironmentProblem, InputError) as problem:
        print(f"glint: the [geometry] field was not checked: {problem}", file=sys.stderr)
        return
    for warning in warnings:
        print(f"glint: warning: {warning}", file=sys.stderr)


def _write_json(shader: Shader, split: bool, output: str | None) -> int:
    """`--format shadertoy-json`: the composition as ShaderToy's JSON, one Image pass (and a
    Common pass with --split common), the scene's pictures as texture inputs."""
    from glint.compiler.files import write_atomic
    from glint.compiler.target.shadertoy_project import (
        ChannelInput,
        Pass,
        Project,
        project_json,
    )

    if shader.target != "shadertoy":
        raise UsageError(
            f"--format shadertoy-json writes ShaderToy's tabs: drop --target {shader.target}"
        )
    scene = shader.scene
    pictures = sorted(scene.picture_files().items())
    inputs = tuple(ChannelInput(unit, "texture", file=file) for unit, file in pictures)
    if split:
        tabs = shader.split_common()
        project = Project("<compose>", (Pass("Image", tabs.image, inputs),), tabs.common)
    else:
        project = Project("<compose>", (Pass("Image", shader.text, inputs),))
    text = json.dumps(project_json(project, scene.name, scene.description), indent=1) + "\n"
    if not output or output == "-":
        sys.stdout.write(text)
        return 0
    write_atomic(Path(output), text.encode("utf-8"))
    beside = (
        f", its pictures ({', '.join(i.file.name for i in inputs if i.file)}) to go beside it"
        if inputs
        else ""
    )
    print(
        f"wrote {output}: ShaderToy JSON, {1 + split} pass{'es' * split}{beside}", file=sys.stderr
    )
    return 0


def _write_split(shader: Shader, output: str | None) -> int:
    """`--split common`: the Image tab to OUTPUT, the Common tab beside it."""
    from glint.compiler.files import is_null_device, write_atomic

    if not output or output == "-":
        raise UsageError(
            "--split common writes two files: give -o IMAGE.glsl (the Common tab goes beside "
            "it as IMAGE.common.glsl)"
        )
    tabs = shader.split_common()
    image = Path(output)
    common = image.with_name(image.stem + ".common" + (image.suffix or ".glsl"))
    if is_null_device(image):  # both tabs thrown away, nothing written beside the device
        common = image
    write_atomic(common, tabs.common.encode("utf-8"))
    write_atomic(image, tabs.image.encode("utf-8"))
    print(f"wrote {common} (Common tab) and {image} (Image tab)", file=sys.stderr)
    return 0


def cmd_bench(args: argparse.Namespace) -> int:
    from glint.compiler.bench.report import tier_table, write_measurements, write_report
    from glint.compiler.bench.run import BenchOptions, run_bench

    if args.update and (args.slots or args.no_variants):
        raise UsageError("--update writes every variant's measurements: drop --slots/--no-variants")
    if args.repeats < 2:
        raise UsageError(
            f"--repeats must be at least 2 (the first draw is not timed), got {args.repeats}"
        )
    options = BenchOptions(
        slots=args.slots,
        scenes=args.scenes,
        size=args.size,
        repeats=args.repeats,
        variants=not args.no_variants,
        tiers=not args.no_scenes,
    )
    result = run_bench(options, _progress_bar)
    renderer = str(result.machine["renderer"])
    timing = "CPU time" if result.machine["cpu"] else "GPU time"
    print(f"measured on {renderer}" + ("" if timing in renderer else f" ({timing})"))
    if result.tiers:
        print("\n".join(tier_table(result.tiers)))
    for goal in result.goals:
        verdict = "reached" if goal.reached else "NOT reached"
        print(f"goal {goal.name}: {verdict}: {goal.measured} (target: {goal.target})")
    if result.variants:
        front = sum(v.pareto for v in result.variants)
        print(f"{len(result.variants)} variants measured, {front} on their slot's front")
    written = write_report(result, Path(args.out), charts=not args.no_charts)
    if args.update:
        written.append(write_measurements(result))
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


@contextmanager
def _progress_bar(label: str, total: int) -> Iterator[Callable[[str], None]]:
    """A tqdm bar on stderr (off when stderr is not a terminal); yields the per-item tick."""
    from tqdm import tqdm

    with tqdm(total=total, desc=label, file=sys.stderr, disable=None) as bar:

        def tick(item: str) -> None:
            bar.set_postfix_str(item)
            bar.update()

        yield tick


def _picture_channel(text: str) -> tuple[int, str]:
    """N=PICTURE for `render --channel`."""
    unit, sep, path = text.partition("=")
    if not sep or unit.strip() not in ("0", "1", "2", "3") or not path:
        raise argparse.ArgumentTypeError(
            f"{printable(text)}: expected N=PICTURE with N a channel from 0 to 3, e.g. 0=stone.png"
        )
    return int(unit), path


def _channel(text: str) -> tuple[int, str]:
    try:
        return channel_binding(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def cmd_validate(args: argparse.Namespace) -> int:
    from glint.compiler.target.glslang import validate

    _refuse_converted(args.file, "validate")
    if is_project(args.file):
        return _validate_project(Path(args.file), args.target)
    source = with_includes(read_text_file(args.file), args.file)
    tab = _validate_tab(args)
    diagnostics = validate(source, args.file, args.target, tab)
    for diagnostic in diagnostics:
        print(diagnostic)
    errors = sum(1 for d in diagnostics if d.severity == "error")
    if errors:
        print(f"{args.file}: {errors} error{'s' if errors > 1 else ''}", file=sys.stderr)
        return 1
    what = "Common tab" if tab.is_common else "shader"
    print(f"{args.file}: valid {args.target} {what} (glslangValidator)")
    return 0


def _validate_project(path: Path, target: str) -> int:
    """Every pass of a ShaderToy project compiled as ShaderToy compiles it: the Common tab in
    front, its channels typed by its inputs; errors under PROJECT:PASS:LINE (a folder's at the
    tab's own file)."""
    from glint.compiler.target.glslang import validate
    from glint.compiler.target.shadertoy_project import read_project

    project = read_project(path, pictures=False)
    errors = 0
    tabs = [(project.common_file or f"{project.origin}:Common", project.common,
             shadertoy.Tab(is_common=True))] if project.common else []  # fmt: skip
    for item in project.passes:
        tab = shadertoy.Tab(common=project.common, common_file=project.common_file,
                            channels=item.channel_kinds())  # fmt: skip
        tabs.append((item.file or f"{project.origin}:{item.name}", item.code, tab))
    for name, code, tab in tabs:
        for diagnostic in validate(code, name, target, tab):
            print(diagnostic)
            errors += diagnostic.severity == "error"
    if errors:
        print(f"{project.origin}: {errors} error{'s' if errors > 1 else ''}", file=sys.stderr)
        return 1
    print(f"{project.origin}: valid {target} project, {len(tabs)} tabs (glslangValidator)")
    return 0


def _validate_tab(args: argparse.Namespace) -> shadertoy.Tab:
    """The ShaderToy tab `validate` compiles the file in: after its Common tab (--common, else
    NAME.common.glsl beside it), with the channels' types; a Common tab alone as ShaderToy does."""
    channels = shadertoy.bind_channels(shadertoy.Tab().channels, args.channel)
    common = Path(args.common) if args.common else shadertoy.common_sibling(args.file)
    if args.common and not common.is_file():
        raise UsageError(f"--common {printable(args.common)}: no such file")
    alone = shadertoy.is_common_file(args.file) or (common.is_file() and common.samefile(args.file))
    if alone or not common.is_file():
        return shadertoy.Tab(channels=channels, is_common=alone)
    text = read_text_file(common)
    return shadertoy.Tab(common=text, common_file=str(common), channels=channels)


def cmd_render(args: argparse.Namespace) -> int:
    import glint

    _refuse_converted(args.input, "render")
    shader: glint.Shader | glint.MeshShader | Path = Path(args.input)
    if args.input.endswith(".toml"):
        variants = _variants(args.variant)
        from glint.compiler.scene.model import load_scene

        scene = load_scene(shader)  # read once: a mesh scene's files are read with it
        if scene.is_mesh:  # rasterized: the programs llvmpipe runs
            shader = glint.compose_mesh(scene, tier=args.tier, variants=variants)
        else:
            shader = glint.compose(scene, tier=args.tier, variants=variants, budget=args.budget)
    width, height = args.size
    image = glint.render(
        shader,
        size=(width, height),
        time=args.time,
        frame=args.frame,
        mouse=args.mouse,
        timeout=args.timeout,
        channels=dict(args.channel) or None,
        frames=args.frames,
    )
    to_stdout = args.output == "-"
    if to_stdout:  # the PNG alone on stdout: the report goes to stderr
        sys.stdout.flush()
        sys.stdout.buffer.write(image.to_png())
        sys.stdout.buffer.flush()
    else:
        image.save(args.output)
    stats = image.stats
    report = {
        "input": args.input,
        "output": args.output,
        "renderer": image.renderer,
        "glsl_version": image.glsl_version,
        "draw_seconds": image.draw_seconds,
        "time": args.time,
        "frame": args.frame,
        **stats,
    }
    out = sys.stderr if to_stdout else sys.stdout
    if args.json:
        # JSON has no NaN or Infinity (json.dumps would write them, and JSON readers refuse
        # them): a figure that is not finite is null, as stats give None where nothing is.
        print(json.dumps(_finite_or_null(report), indent=2, allow_nan=False), file=out)
    else:
        where = "standard output" if to_stdout else args.output
        size = f"{width}x{height}, iTime {args.time}"
        if args.frames > 1:  # a project's frames: the last one is written
            size += f" to {args.time + (args.frames - 1) / 60:.4g}, {args.frames} frames"
        print(f"wrote {where} ({size}) with {image.renderer}", file=out)
        print(
            f"  NaN pixels: {stats['nan']}, Inf pixels: {stats['inf']}, "
            f"range [{_num(stats['finite_min'])}, {_num(stats['finite_max'])}], "
            f"mean RGB {', '.join(_num(v) for v in stats['mean'])}",
            file=out,
        )
    return 1 if stats["nan"] or stats["inf"] else 0


def _finite_or_null(value: object) -> object:
    """`value` with every float that is NaN or infinite, at any depth, replaced by None."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {key: _finite_or_null(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_finite_or_null(item) for item in value]
    return value


# Suffixes of the HLSL and Metal files `compose --target hlsl|msl` writes.
_CONVERTED = {".hlsl": "HLSL", ".fx": "HLSL", ".metal": "MSL", ".msl": "MSL"}


def _refuse_converted(path: str, command: str) -> None:
    """validate and render take GLSL; say so for an HLSL or Metal file instead of glslang's
    errors on it."""
    lang = _CONVERTED.get(Path(path).suffix.lower())
    if lang:
        raise UsageError(
            f"{path}: glint {command} takes GLSL (ShaderToy Image-tab code), not {lang}; "
            f"{command} the GLSL that `glint compose` writes, then convert it with --target"
        )


def _num(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.4g}"


def cmd_catalog(args: argparse.Namespace) -> int:
    from glint.compiler.catalog.info import catalog_entries

    entries = catalog_entries()
    if args.json:
        print(json.dumps(entries, indent=2))
        return 0
    for entry in entries:
        print(f"{entry['id']}  [{entry['slot']}]  {entry['summary']}")
        for signature in entry["signature"]:
            print(f"    {signature}")
        if entry["requires"]:
            print(f"    requires: {', '.join(entry['requires'])}")
        if entry["params"]:
            knobs = ", ".join(f"{p['name']}={p['default']}" for p in entry["params"])
            print(f"    params: {knobs}")
        print(f"    sources: {'; '.join(entry['sources'])}")
        print(f"    file: {entry['file']}")
    return 0


def cmd_catalog_show(args: argparse.Namespace) -> int:
    from glint.compiler.catalog_tools.cross import show_in

    sys.stdout.write(show_in(args.id, args.lang))
    return 0


if __name__ == "__main__":
    sys.exit(main())
