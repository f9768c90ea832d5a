"""The ShaderToy environment: the prelude that ShaderToy puts in front of an Image-tab shader.

ShaderToy compiles the Image tab as GLSL ES 3.00 with these uniforms declared for it; glint
validates and renders user code with exactly this prelude so that what passes here pastes there.
"""

from __future__ import annotations

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
