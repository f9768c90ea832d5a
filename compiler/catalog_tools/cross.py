"""`glint catalog show ID --lang hlsl|msl`: the block of `catalog show`, converted through SPIR-V.

A snippet has no entry point, and SPIR-V keeps only what an entry point reaches, so the GLSL
block gets a small `main` that calls each function the snippet provides once (arguments taken
from the pixel position, results added into the output) and stand-ins for the scene functions
the block declares (`map`, ...), which SPIR-V needs defined. SPIRV-Cross does the conversion;
the functions keep their GLSL names and parameters.
"""

from __future__ import annotations

import re

from glint.compiler.catalog.loader import Catalog, load_catalog
from glint.compiler.catalog.slots import SCENE_FUNCTIONS
from glint.compiler.catalog_tools.show import show_source
from glint.compiler.errors import UsageError
from glint.compiler.glsl.symbols import FunctionDef, analyze
from glint.compiler.glsl.types import is_scalar_constructible, size
from glint.compiler.target import cross
from glint.compiler.target.shadertoy import UNIFORM_NAMES

_NAMES = {"hlsl": "HLSL (shader model 5.0)", "msl": "Metal Shading Language"}


def show_in(snippet_id: str, lang: str, catalog: Catalog | None = None) -> str:
    """The snippet and what it needs as HLSL or MSL; `glsl` gives `catalog show`'s block."""
    catalog = catalog or load_catalog()
    block = show_source(snippet_id, catalog)
    if lang == "glsl":
        return block
    if lang not in cross.LANGS:
        raise UsageError(f"unknown language {lang!r}; expected glsl, hlsl or msl")
    snippet = catalog.get(snippet_id)
    defined = analyze(block, snippet.relpath, provided=UNIFORM_NAMES).functions
    provided = [f for f in defined if f.name in snippet.provides]
    stand_ins = [name for name, proto in SCENE_FUNCTIONS.items() if f"\n{proto};\n" in block]
    code = block + _stand_ins(stand_ins) + entry_main(provided)
    header = cross.prelude(code)
    converted = cross.cross_compile(
        header + code, lang, snippet.file or snippet.relpath, code, header.count("\n")
    )
    return _comment(block, snippet_id, lang, stand_ins) + converted


def entry_main(functions: list[FunctionDef]) -> str:
    """A fragment `main` that calls each function once and adds its result to the output, so
    that SPIR-V keeps it. Arguments are built from gl_FragCoord.x (so nothing folds away);
    structs, arrays and out parameters are locals."""
    lines = [
        "",
        "layout(location = 0) out vec4 glintOut;",
        "void main() {",
        "    float x = gl_FragCoord.x;",
        "    vec4 sum = vec4(0.0);",
    ]
    for function in functions:
        args = []
        lines.append("    {")
        for index, param in enumerate(function.params):
            name = f"arg{index}"
            writes = "out" in param.qualifier.split()
            if is_scalar_constructible(param.type) and not writes:
                lines.append(f"        {param.type} {name} = {param.type}(x);")
            else:
                lines.append(f"        {param.type} {name};")
            args.append(name)
        call = f"{function.name}({', '.join(args)})"
        lines.append(f"        {_use(function.return_type, call)}")
        lines.append("    }")
    lines += ["    glintOut = sum;", "}", ""]
    return "\n".join(lines)


def _use(return_type: str, call: str) -> str:
    n = size(return_type)
    if n == 1:
        return f"sum.x += float({call});"
    if n:
        return f"sum.{'xyzw'[:n]} += vec{n}({call});"
    return f"{call};"  # a matrix, a struct or void: the call alone keeps the function


def _stand_ins(names: list[str]) -> str:
    """Definitions for the scene functions the block declares: zero, to be replaced."""
    if not names:
        return ""
    lines = ["", "// Stand-ins for your scene (replace them)."]
    for name in names:
        proto = SCENE_FUNCTIONS[name]
        result = proto.split()[0]
        if result != "void":
            lines.append(f"{proto} {{ return {result}(0); }}")
            continue
        # a function that answers through out parameters: each set to 0
        outs = re.findall(r"\bout\s+(\w+)\s+(\w+)", proto)
        lines.append(f"{proto} {{ {' '.join(f'{n} = {t}(0);' for t, n in outs)} }}")
    return "\n".join(lines) + "\n"


def _comment(block: str, snippet_id: str, lang: str, stand_ins: list[str]) -> str:
    """`catalog show`'s header (what was pulled in and why) and what the conversion added."""
    header = block.split("\n\n", 1)[0].splitlines()
    header = [line for line in header if line.startswith("//")]
    shown = f"catalog show {snippet_id}"
    header[0] = header[0].replace(shown, f"{shown} --lang {lang}", 1)
    header += [
        f"// Converted to {_NAMES[lang]} through SPIR-V (glslangValidator -V, SPIRV-Cross).",
        "// The #define parameters are named constants (SPIRV_CROSS_CONSTANT_ID_n overrides one)."
        if lang == "hlsl"
        else "// The #define parameters are named constants (function constants override them).",
        "// The entry point only calls each function once so that it survives the conversion;",
        "// drop it, or ignore it, when you include the functions in your own shader.",
    ]
    if stand_ins:
        names = ", ".join(stand_ins)
        header.append(f"// {names}: stand-ins that return 0; define your scene's instead.")
    return "\n".join(header) + "\n\n"
