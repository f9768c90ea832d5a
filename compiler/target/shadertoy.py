"""The ShaderToy environment: the prelude that ShaderToy puts in front of an Image-tab shader.

ShaderToy compiles the Image tab as GLSL ES 3.00 with these uniforms declared for it; glint
validates and renders user code with exactly this prelude so that what passes here pastes there.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

# Uniforms ShaderToy declares for the Image tab (https://www.shadertoy.com/howto).
UNIFORMS: tuple[tuple[str, str], ...] = (
    ("vec3", "iResolution"),
    ("float", "iTime"),
    ("float", "iTimeDelta"),
    ("int", "iFrame"),
    ("float", "iFrameRate"),
    ("vec4", "iMouse"),
    ("vec4", "iDate"),
    ("float", "iChannelTime[4]"),
    ("vec3", "iChannelResolution[4]"),
    ("float", "iSampleRate"),
    ("sampler2D", "iChannel0"),
    ("sampler2D", "iChannel1"),
    ("sampler2D", "iChannel2"),
    ("sampler2D", "iChannel3"),
)

UNIFORM_NAMES: frozenset[str] = frozenset(decl.split("[")[0] for _, decl in UNIFORMS)

_HEADER = (
    "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
)

_UNIFORM_BLOCK = "".join(f"uniform {ty} {decl};\n" for ty, decl in UNIFORMS)

# The entry point ShaderToy appends after the user's code.
EPILOGUE = (
    "\nout vec4 glintFragColor;\n"
    "void main() {\n"
    "    glintFragColor = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "    mainImage(glintFragColor, gl_FragCoord.xy);\n"
    "}\n"
)

# Where a composed or validated shader is meant to run; `wrap_for` gives each its prelude.
TARGETS = ("shadertoy", "webgl2", "desktop")

PRELUDE = _HEADER + _UNIFORM_BLOCK
# Number of lines the prelude adds in front of the user's first line.
PRELUDE_LINES = PRELUDE.count("\n")


def wrap(user_source: str) -> str:
    """Return a complete fragment shader: prelude, the user's code unchanged, then `main`."""
    body = user_source if user_source.endswith("\n") else user_source + "\n"
    return PRELUDE + body + EPILOGUE


# Desktop GL: the same uniforms under `#version 330`, where precision statements are not needed.
DESKTOP_PRELUDE = "#version 330\n" + _UNIFORM_BLOCK


def prelude_lines(target: str) -> int:
    """How many lines `wrap_for(target, ...)` puts before the user's first line."""
    return {"shadertoy": 0, "webgl2": PRELUDE_LINES, "desktop": DESKTOP_PRELUDE.count("\n")}[target]


# What `--channel N=KIND` binds to iChannelN, and the sampler type ShaderToy then declares.
CHANNEL_KINDS: dict[str, str] = {"2d": "sampler2D", "cube": "samplerCube", "3d": "sampler3D"}
CHANNELS = 4

# The type of every name ShaderToy provides: its uniforms (an array declarator's size goes with
# the type: iChannelTime is a float[4]) and the fragment stage's variables.
SHADERTOY_TYPES: dict[str, str] = {
    decl.partition("[")[0]: ty + "".join(f"[{rest}" for rest in decl.split("[")[1:])
    for ty, decl in UNIFORMS
}
SHADERTOY_TYPES.update(
    {"gl_FragCoord": "vec4", "gl_FrontFacing": "bool", "gl_PointCoord": "vec2",
     "gl_FragDepth": "float"}
)  # fmt: skip


def shadertoy_types(channels: Sequence[str] = ()) -> dict[str, str]:
    """SHADERTOY_TYPES with iChannelN typed for what it is bound to ("2d", "cube", "3d")."""
    types = dict(SHADERTOY_TYPES)
    for index, kind in enumerate(channels):
        types[f"iChannel{index}"] = CHANNEL_KINDS[kind]
    return types


# ShaderToy's prelude defines HW_PERFORMANCE before the code: 1 on desktops, 0 on phones.
# glint checks the desktop's value. Code that defines it itself (written for a runner that
# does not) keeps its own value: a redefinition with another value would be an error
# (glslang and glint's preprocessor agree), so then the prelude leaves it out.
HW_PERFORMANCE = "1"
_DEFINES_HW_PERFORMANCE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+HW_PERFORMANCE\b", re.M)

# The Common tab compiled on its own: ShaderToy declares only these uniforms for it (the
# others belong to a pass) and a `main` of its own, so it needs no mainImage.
COMMON_UNIFORMS: tuple[tuple[str, str], ...] = (("vec4", "iDate"), ("float", "iSampleRate"))
COMMON_EPILOGUE = "\nout vec4 glintFragColor;\nvoid main() { glintFragColor = vec4(0.0); }\n"


@dataclass(frozen=True)
class Tab:
    """ShaderToy's world around one tab's code: the Common tab's code that ShaderToy puts in
    front of it, what each iChannelN is bound to, and whether the code is the Common tab."""

    common: str = ""  # the Common tab's code ("" when there is none)
    common_file: str = ""  # where that code came from, for messages
    channels: tuple[str, ...] = ("2d",) * CHANNELS  # a CHANNEL_KINDS key per channel
    is_common: bool = False  # the code is itself a Common tab, compiled alone


def channel_binding(text: str) -> tuple[int, str]:
    """`N=KIND` as `--channel` takes it: (N, KIND); ValueError saying what it takes."""
    number, _, kind = text.partition("=")
    kind = kind.strip().lower()
    if number.strip() not in {str(i) for i in range(CHANNELS)} or kind not in CHANNEL_KINDS:
        raise ValueError(
            f"expected N=KIND with N 0 to {CHANNELS - 1} and KIND one of "
            f"{', '.join(CHANNEL_KINDS)} (e.g. 0=cube), got {text!r}"
        )
    return int(number), kind


def bind_channels(channels: tuple[str, ...], bindings: list[tuple[int, str]]) -> tuple[str, ...]:
    """`channels` with each (N, KIND) of `bindings` bound."""
    bound = list(channels)
    for index, kind in bindings:
        bound[index] = kind
    return tuple(bound)


def common_sibling(path: str | Path) -> Path:
    """`NAME.common.glsl` beside `NAME.glsl`: where `glint compose --split common` writes the
    Common tab of an Image tab."""
    path = Path(path)
    return path.with_name(path.stem + ".common" + (path.suffix or ".glsl"))


def is_common_file(path: str | Path) -> bool:
    """Whether the file is named as a Common tab (`NAME.common.glsl`)."""
    return Path(path).stem.endswith(".common")


def predefined_macros(target: str, code: str) -> dict[str, str]:
    """The macros the target defines before `code` (the Common tab's code included)."""
    if target != "shadertoy" or _DEFINES_HW_PERFORMANCE.search(code):
        return {}
    return {"HW_PERFORMANCE": HW_PERFORMANCE}


def wrap_tab(target: str, user_source: str, tab: Tab) -> tuple[str, int]:
    """The complete fragment shader that checks `user_source` as `target` runs it within
    `tab` (`shadertoy` is checked as `webgl2`, with ShaderToy's own macros), and how many
    lines come before the user's first line: the prelude, then the Common tab's code."""
    body = user_source if user_source.endswith("\n") else user_source + "\n"
    common = tab.common if not tab.common or tab.common.endswith("\n") else tab.common + "\n"
    head = "#version 330\n" if target == "desktop" else _HEADER
    for name, value in predefined_macros(target, common + body).items():
        head += f"#define {name} {value}\n"
    if tab.is_common and target == "shadertoy":
        uniforms = COMMON_UNIFORMS
    else:
        channels = {f"iChannel{i}": CHANNEL_KINDS[kind] for i, kind in enumerate(tab.channels)}
        uniforms = tuple((channels.get(decl, ty), decl) for ty, decl in UNIFORMS)
    head += "".join(f"uniform {ty} {decl};\n" for ty, decl in uniforms)
    prelude = head + ("" if tab.is_common else common)
    epilogue = COMMON_EPILOGUE if tab.is_common else EPILOGUE
    return prelude + body + epilogue, prelude.count("\n")


def is_complete(source: str) -> bool:
    """Whether the source is a whole shader (opens with #version) rather than Image-tab code."""
    return source.lstrip().startswith("#version")


def wrap_for(target: str, user_source: str) -> str:
    """The shader as `target` needs it: ShaderToy's Image tab takes the user code as it is;
    `webgl2` and `desktop` are complete fragment shaders with their own prelude and `main`."""
    if target == "shadertoy":
        return user_source
    body = user_source if user_source.endswith("\n") else user_source + "\n"
    if target == "webgl2":
        return PRELUDE + body + EPILOGUE
    if target == "desktop":
        return DESKTOP_PRELUDE + body + EPILOGUE
    raise ValueError(f"unknown target {target!r}")
