"""GLSL to HLSL and Metal (MSL) through SPIR-V: glslangValidator, then SPIRV-Cross.

glslang compiles a complete fragment shader to SPIR-V and SPIRV-Cross (Debian's `spirv-cross`)
writes that SPIR-V as HLSL or MSL; neither language is written here. What is written here is
the glue around them: the Vulkan GLSL fragment shader that holds ShaderToy's Image-tab code,
scalar `#define` parameters turned into named constants, and the check that compiles the HLSL
back with glslang's own HLSL front end.

Why Vulkan semantics (`glslangValidator -V`) rather than OpenGL's (`-G`): Vulkan GLSL has no
loose uniforms, so ShaderToy's uniforms go in one std140 block, which SPIRV-Cross writes as an
HLSL `cbuffer` with explicit packing and as an MSL `constant` struct at buffer(0) - what Unity,
D3D and Metal bind - instead of HLSL globals in an implicit `$Globals` buffer; and `-V` gives
specialization constants (`layout(constant_id)`), which SPIRV-Cross writes as overridable named
constants. OpenGL-flavoured SPIR-V buys nothing here: the output is for D3D and Metal.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile

from glint.compiler.errors import EnvironmentProblem, InputError, UsageError
from glint.compiler.target import shadertoy, tools
from glint.compiler.target.glslang import find_validator, parse_output

LANGS = ("hlsl", "msl")
# Shader model 5.0: D3D11 and every Unity platform that compiles HLSL; the catalog needs nothing
# newer (no 16-bit types, no wave intrinsics).
SHADER_MODEL = "50"
ENTRY = "main"  # the entry point SPIRV-Cross gives an HLSL shader (MSL: `main0`)
# What a converted file is, for its header comment.
DESCRIPTIONS = {
    "hlsl": "An HLSL pixel shader (shader model 5.0, entry `main`); ShaderToy's uniforms are in\n"
    "// cbuffer ShaderToy (register b0), iChannelN in tN and sN.",
    "msl": "A Metal fragment function (`main0`); ShaderToy's uniforms are a ShaderToy struct\n"
    "// at buffer(0).",
}
TIMEOUT_S = 30.0
SPIRV_CROSS_INSTALL = "install it with `sudo apt-get install spirv-cross` (Debian) or `make setup`"

# GLSL ES 3.10 is the first ES version glslang compiles to SPIR-V; ShaderToy's ES 3.00 is a
# subset of it.
HEADER = "#version 310 es\nprecision highp float;\nprecision highp int;\n"
# ShaderToy's uniforms as one block (a cbuffer in HLSL), the channels with bindings of their own.
_BLOCK = (
    "layout(std140, binding = 0) uniform ShaderToy {\n"
    + "".join(f"    {ty} {decl};\n" for ty, decl in shadertoy.UNIFORMS if ty != "sampler2D")
    + "};\n"
    + "".join(f"layout(binding = {i + 1}) uniform highp sampler2D iChannel{i};\n" for i in range(4))
)
IMAGE_PRELUDE = HEADER + _BLOCK
# ShaderToy's fragCoord counts from the bottom row (OpenGL); SV_Position and Metal's
# [[position]] count from the top, so the entry flips y before it calls mainImage.
IMAGE_EPILOGUE = (
    "\nlayout(location = 0) out vec4 glintFragColor;\n"
    "void main() {\n"
    "    vec4 color = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "    mainImage(color, vec2(gl_FragCoord.x, iResolution.y - gl_FragCoord.y));\n"
    "    glintFragColor = color;\n"
    "}\n"
)

# `#define NAME 1.5` / `#define NAME 64` / `#define NAME true` on a line of its own: a parameter
# that can become a named constant. Expressions and vectors stay macros (glslang inlines them).
_SCALAR_DEFINE = re.compile(
    r"^[ \t]*#define[ \t]+([A-Za-z_]\w*)[ \t]+"
    r"(true|false|[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?)[ \t]*(//.*)?$",
    re.M,
)
# SPIRV-Cross names the members of an anonymous block's cbuffer `_<id>_<member>`.
_CBUFFER_MEMBER = re.compile(r"\b_(\d+)_(" + "|".join(sorted(shadertoy.UNIFORM_NAMES)) + r")\b")


def find_spirv_cross() -> str:
    """Return the path of spirv-cross, or say how to install it."""
    path = shutil.which("spirv-cross")
    if path is None:
        raise EnvironmentProblem(
            f"spirv-cross not found (needed for HLSL and MSL); {SPIRV_CROSS_INSTALL}"
        )
    return path


def prelude(source: str) -> str:
    """The Vulkan GLSL header for `source`, with ShaderToy's uniforms where it uses any."""
    uses = any(re.search(rf"\b{name}\b", source) for name in shadertoy.UNIFORM_NAMES)
    return IMAGE_PRELUDE if uses else HEADER


def image_shader(image_source: str) -> tuple[str, int]:
    """ShaderToy Image-tab code as a Vulkan GLSL fragment shader, and how many lines precede the
    user's first line."""
    body = image_source if image_source.endswith("\n") else image_source + "\n"
    return IMAGE_PRELUDE + body + IMAGE_EPILOGUE, IMAGE_PRELUDE.count("\n")


def named_constants(source: str) -> str:
    """Each scalar `#define NAME value` as a specialization constant of the same name, line for
    line, so that the parameter keeps its name in HLSL and MSL (and can be overridden there)."""
    counter = iter(range(1 << 16))

    def constant(match: re.Match[str]) -> str:
        name, value = match.group(1), match.group(2)
        if value in ("true", "false"):
            type_ = "bool"
        elif re.search(r"[.eE]", value):
            type_ = "float"
        else:
            type_ = "int"
        return f"layout(constant_id = {next(counter)}) const {type_} {name} = {value};"

    return _SCALAR_DEFINE.sub(constant, source)


def cross_compile_image(image_source: str, lang: str, filename: str = "<input>") -> str:
    """ShaderToy Image-tab code (what `--target shadertoy` writes) as an HLSL or MSL fragment
    shader: the uniforms in a cbuffer / constant buffer, `mainImage` called by the entry point
    with the pixel position. InputError, at the user's lines, when the GLSL does not compile."""
    glsl, prelude = image_shader(image_source)
    return cross_compile(glsl, lang, filename, image_source, prelude)


def cross_compile(
    glsl: str,
    lang: str,
    filename: str = "<input>",
    user_source: str | None = None,
    prelude_lines: int = 0,
) -> str:
    """A complete Vulkan GLSL fragment shader as HLSL (shader model 5.0) or MSL.

    Scalar `#define`s become named constants where the shader compiles that way (not where it
    needs them in `#if` or other preprocessor logic); otherwise they stay macros and SPIRV-Cross
    writes their values. Errors are mapped to `user_source` (the code after `prelude_lines`
    lines of `glsl`) as `glint validate` maps them."""
    if lang not in LANGS:
        raise UsageError(f"unknown language {lang!r}; expected one of: glsl, {', '.join(LANGS)}")
    spirv_cross = find_spirv_cross()
    with tempfile.TemporaryDirectory(prefix="glint-cross-") as workdir:
        spirv = os.path.join(workdir, "shader.spv")
        result = _to_spirv(named_constants(glsl), workdir, spirv)
        if result.returncode != 0:
            result = _to_spirv(glsl, workdir, spirv)
        if result.returncode != 0:
            output = result.stdout + result.stderr
            source = glsl[_offset(glsl, prelude_lines) :] if user_source is None else user_source
            diagnostics = parse_output(output, source, filename, prelude_lines)
            detail = "; ".join(str(d) for d in diagnostics if d.severity == "error")
            raise InputError(f"cannot convert to {lang.upper()}: {detail or output.strip()}")
        flags = ["--hlsl", "--shader-model", SHADER_MODEL] if lang == "hlsl" else ["--msl"]
        converted = _run([spirv_cross, spirv, *flags])
    if converted.returncode != 0:
        raise EnvironmentProblem(f"spirv-cross failed: {converted.stderr.strip()}")
    text = converted.stdout
    return _member_names(text) if lang == "hlsl" else text


def _offset(text: str, lines: int) -> int:
    index = 0
    for _ in range(lines):
        index = text.index("\n", index) + 1
    return index


def _to_spirv(glsl: str, workdir: str, spirv: str) -> subprocess.CompletedProcess[str]:
    shader = os.path.join(workdir, "shader.frag")
    with open(shader, "w", encoding="utf-8") as handle:
        handle.write(glsl)
    # -V: Vulkan semantics (see the module's docstring). OpName debug names are kept by default,
    # so functions, parameters, structs and constants keep their GLSL names.
    return _run([find_validator(), "-V", "-o", spirv, shader])


def _member_names(hlsl: str) -> str:
    """ShaderToy's uniforms by their own names in the cbuffer (`iTime`, not `_71_iTime`)."""
    return _CBUFFER_MEMBER.sub(lambda m: m.group(2), hlsl)


def check_hlsl(hlsl: str, entry: str = ENTRY) -> list[str]:
    """Compile HLSL back with glslang's HLSL front end (`glslangValidator -D`, to SPIR-V as it
    must be) as a pixel shader; the error lines, empty when it compiles."""
    with tempfile.TemporaryDirectory(prefix="glint-cross-") as workdir:
        path = os.path.join(workdir, "shader.hlsl")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(hlsl)
        spirv = os.path.join(workdir, "shader.spv")
        result = _run([find_validator(), "-D", "-V", "-S", "frag", "-e", entry, "-o", spirv, path])
    output = result.stdout + result.stderr
    errors = [line for line in output.splitlines() if line.startswith("ERROR")]
    if result.returncode != 0 and not errors:
        errors = [output.strip() or f"glslangValidator exit status {result.returncode}"]
    return errors


def _run(args: list[str]) -> subprocess.CompletedProcess[str]:
    """The tool's output, decoded; ToolLimit (an InputError) when the shader makes it run out
    of time or memory (tools.py)."""
    return tools.run_tool(args, TIMEOUT_S)
