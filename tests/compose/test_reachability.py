"""Emission keeps only what mainImage reaches: every item left in a composed shader is used,
the shader still validates, and every line still maps to its line in the snippet file."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from lark import Token, Tree
from mesh_scenes import MESH_EXAMPLES, RAYMARCHED_EXAMPLES

from glint import compose, compose_mesh
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.compose.linking.emitter import emit
from glint.compiler.compose.linking.reachability import prune_unreachable
from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.units import GENERATED, Unit, generated
from glint.compiler.glsl import parse_source
from glint.compiler.scene.model import default_scene_path, parse_scene
from glint.compiler.target.glslang import validate
from glint.compiler.target.sourcemap import build_line_map

ROOT = Path(__file__).resolve().parents[2]
SCENES = RAYMARCHED_EXAMPLES  # the ShaderToy shaders; the mesh examples are tested below
assert SCENES[0] == default_scene_path()
TIERS = ["fast", "balanced", "reference"]
# Overrides that bring in snippets defining several functions (a helper and the entry).
MULTI_FUNCTION = [
    {"V": "smith_beckmann"},
    {"D": "blinn_phong", "specular": "blinn_phong"},
    {"diffuse": "burley"},
    {"diffuse": "oren_nayar"},
    {"diffuse": "toon"},
    {"ibl": "env_brdf_approx"},
]
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)

# No direct light: core.surface comes for `Surface`, but nothing calls `lightDots` or uses `Dots`.
UNLIT = """
name = "unlit"
[[objects]]
shape = "box"
size = [0.5, 0.5, 0.5]
material = "grey"
[materials.grey]
albedo = [0.5, 0.5, 0.5]
[camera]
type = "lookat"
position = [2.0, 2.0, 3.0]
[[lights]]
type = "sky"
[effects]
ao = false
[environment]
reflection = false
"""


# -- an independent check: what the output defines, and what reaches what -----------------------


def unreachable_items(text: str, root: str = "mainImage") -> set[str]:
    """Top-level names of a shader that `root` does not reach, with references taken as
    every identifier an item's tokens name (fields excepted), which over-approximates use."""
    tree, pre = parse_source(text, "out.glsl")
    refs: dict[str, set[str]] = {}
    for node in tree.children:
        names = top_level_names(node)
        used = identifiers(node)
        for line in range(node.meta.line, node.meta.end_line + 1):
            used |= pre.expansions.get(line, set())  # macros the preprocessor expanded there
        for name in names:
            refs.setdefault(name, set()).update(used)
    for macro in pre.defines.values():
        if macro.file != "<predefined>":
            refs.setdefault(macro.name, set()).update(
                re.findall(r"(?<!\.)\b[A-Za-z_]\w*", macro.body)
            )
    seen: set[str] = set()
    todo = [root]
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.add(name)
            todo.extend(refs.get(name, ()))
    return set(refs) - seen


def top_level_names(node: Tree) -> set[str]:
    if node.data == "function_definition":
        return {str(node.children[0].children[1])}
    if node.data == "function_prototype":
        return {str(node.children[1])}
    names = {
        str(c.children[0]) for c in node.children if isinstance(c, Tree) and c.data == "declarator"
    }
    for struct in node.find_data("struct_specifier"):
        names |= {str(t) for t in struct.children[:1] if isinstance(t, Token)}
    return names


def identifiers(node: Tree) -> set[str]:
    found: set[str] = set()
    for sub in node.iter_subtrees():
        children = sub.children[:-1] if sub.data == "field" else sub.children
        found |= {
            str(t)
            for t in children
            if isinstance(t, Token) and t.type in ("IDENTIFIER", "TYPE_NAME")
        }
    return found


def mismatched_lines(text: str) -> list[str]:
    """Output lines whose source marker points at a different line of the snippet file."""
    wrong = []
    for line, origin in zip(text.split("\n"), build_line_map(text, "out.glsl"), strict=False):
        if origin.file.startswith("snippets/"):
            source = (ROOT / origin.file).read_text(encoding="utf-8").split("\n")
            if source[origin.line - 1] != line:
                wrong.append(f"{origin.file}:{origin.line}: {line!r}")
    return wrong


# -- every example scene, every tier ------------------------------------------------------------


CASES = [(scene, tier, {}) for scene in RAYMARCHED_EXAMPLES for tier in TIERS]
CASES += [(SCENES[0], "balanced", overrides) for overrides in MULTI_FUNCTION]
# An interface declaration of a mesh stage (three.js' attributes and uniforms, the varyings)
# is there for the program's other stage or the host, whether main reads it or not.
INTERFACE = re.compile(r"^(?:in|out|uniform) \w+ (\w+);", re.M)


@pytest.mark.parametrize(
    ("scene", "tier", "overrides"),
    CASES,
    ids=[f"{s.stem}-{t}-{'-'.join(o.values()) or 'plan'}" for s, t, o in CASES],
)
def test_composed_shader_holds_only_reachable_items(
    scene: Path, tier: str, overrides: dict[str, str]
) -> None:
    text = compose(scene, tier=tier, variants=overrides).text
    assert unreachable_items(text) == set()
    assert mismatched_lines(text) == []


@pytest.mark.parametrize("scene", MESH_EXAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("tier", TIERS)
def test_mesh_stages_hold_only_what_main_reaches(scene: Path, tier: str) -> None:
    """Each stage of each material's program is pruned from its own main (the mesh examples;
    their shaders are validated in test_example_scenes)."""
    for program in compose_mesh(scene, target="mesh-webgl2", tier=tier).programs:
        for stage in (program.vertex, program.fragment):
            interface = set(INTERFACE.findall(stage.text))
            assert unreachable_items(stage.text, "main") - interface == set(), program.material
            assert mismatched_lines(stage.text) == []


@needs_glslang
@pytest.mark.parametrize(
    ("scene", "tier", "overrides"),
    CASES,
    ids=[f"{s.stem}-{t}-{'-'.join(o.values()) or 'plan'}" for s, t, o in CASES],
)
def test_composed_shader_validates(scene: Path, tier: str, overrides: dict[str, str]) -> None:
    text = compose(scene, tier=tier, variants=overrides).text
    assert [str(d) for d in validate(text, f"{scene.stem}.glsl")] == []


def test_a_scene_without_direct_light_loses_the_light_dot_products() -> None:
    shader = compose_scene(parse_scene(UNLIT))
    body = load_catalog().get("core.surface").body
    assert "Dots lightDots(" in body and "struct Dots" in body
    assert "core.surface" in {u.id for u in shader.units}
    assert "lightDots" not in shader.text and "Dots" not in shader.text
    # Its comment went with it; the other items keep theirs.
    assert "The dot products of one light direction" not in shader.text
    assert "// Everything about the point being shaded." in shader.text
    # The snippet was cut in two: the second piece has its own marker, at the right line.
    assert shader.text.count("// source: snippets/core/surface.glsl:") == 2
    assert mismatched_lines(shader.text) == []
    assert unreachable_items(shader.text) == set()


@needs_glslang
def test_a_pruned_shader_validates() -> None:
    assert validate(compose_scene(parse_scene(UNLIT)).text, "unlit.glsl") == []


def test_the_check_sees_an_unreachable_item() -> None:
    """The independent check would catch an item left behind."""
    text = compose().text.replace("void mainImage", "float unused() { return PI; }\nvoid mainImage")
    assert unreachable_items(text) == {"unused"}


# -- pruning small unit lists ------------------------------------------------------------------


MAIN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(%s);\n}\n"


def snippet(body: str, unit_id: str = "t.snip", line: int = 10) -> Unit:
    return Unit(unit_id, "t", (), (), body, f"snippets/t/{unit_id}.glsl", line)


def main(expression: str) -> Unit:
    return generated("scene.main", ["mainImage"], [], MAIN % expression)


def pruned_text(*units: Unit) -> str:
    return "".join(u.body for u in prune_unreachable(list(units)))


def test_a_macro_used_only_by_an_unused_function_goes() -> None:
    lib = snippet("#define K 2.0\nfloat unused() { return K; }\nfloat used() { return 1.0; }\n")
    text = pruned_text(lib, main("used()"))
    assert "K" not in text and "unused" not in text and "float used()" in text


def test_a_macro_named_in_another_macros_replacement_stays() -> None:
    lib = snippet("#define BASE 2.0\n#define TWICE (BASE * 2.0)\n#define UNUSED 3.0\n")
    text = pruned_text(lib, main("TWICE"))
    assert "#define BASE 2.0" in text and "#define TWICE" in text and "UNUSED" not in text


def test_a_macro_from_another_unit_is_reached_through_its_name() -> None:
    constants = generated("scene.constants", [], [], "#define SUN 1.0\n#define MOON 2.0\n")
    lib = snippet("float light() { return SUN; }\n")
    text = pruned_text(constants, lib, main("light()"))
    assert "#define SUN 1.0" in text and "MOON" not in text


def test_a_struct_used_only_as_a_parameter_type_of_a_kept_function_stays() -> None:
    lib = snippet(
        "struct Pair { float a; float b; };\n"
        "struct Lone { float c; };\n"
        "float sum(Pair p) { return p.a + p.b; }\n"
    )
    caller = snippet("float go() { Pair q; q.a = 1.0; q.b = 2.0; return sum(q); }\n", "t.call")
    text = pruned_text(lib, caller, main("go()"))
    assert "struct Pair" in text and "Lone" not in text


def test_the_prototype_of_a_removed_function_goes() -> None:
    lib = snippet(
        "float later(float x);\nfloat kept(float x);\n"
        "float kept(float x) { return x; }\nfloat later(float x) { return 2.0 * x; }\n"
    )
    text = pruned_text(lib, main("kept(1.0)"))
    assert "later" not in text and text.count("float kept(float x)") == 2


def test_unused_global_constants_go_and_used_ones_stay() -> None:
    lib = snippet("const float A = 1.0;\nconst float B = A * 2.0;\nconst float C = 3.0;\n")
    text = pruned_text(lib, main("B"))
    assert "const float A" in text and "const float B" in text and "float C" not in text


def test_comments_go_with_their_item_and_a_group_comment_with_its_last_item() -> None:
    constants = generated(
        "scene.constants",
        [],
        [],
        "// Lights.\n#define SUN 1.0\n// Parameters.\n#define P1 1.0\n#define P2 2.0\n",
    )
    lib = snippet(
        "// Says what dead() does.\nfloat dead() { return SUN; }\n\nfloat f() { return P2; }\n"
    )
    text = pruned_text(constants, lib, main("f()"))
    assert "Lights" not in text and "SUN" not in text  # every item below the comment went
    assert "// Parameters.\n#define P2 2.0" in text  # one of the group is left
    assert "dead" not in text


def test_a_unit_left_with_no_code_goes_and_an_untouched_unit_is_the_same() -> None:
    dead = snippet("// Only a helper.\nfloat helper() { return 1.0; }\n", "t.dead")
    live = snippet("float f() { return 1.0; }\n", "t.live")
    units = prune_unreachable([dead, live, main("f()")])
    assert [u.id for u in units] == ["t.live", "scene.main"]
    assert units[0] is live
    header = emit("t", Plan(tier="balanced"), units, "shadertoy", "0").split("// source:")[0]
    assert "t.live" in header and "t.dead" not in header


def test_a_unit_cut_in_pieces_maps_every_line_to_its_source(tmp_path: Path) -> None:
    source = (
        "/* front matter */\n"  # line 1; the body starts on line 2
        "\n"
        "// A kept.\n"
        "float a() { return 1.0; }\n"
        "\n"
        "// B goes.\n"
        "float b() { return 2.0; }\n"
        "\n"
        "float c() {\n"
        "    return a() + 3.0;\n"
        "}\n"
        "float d() { return 4.0; }\n"
        "float e() { return 5.0; }\n"
    )
    path = tmp_path / "lib.glsl"
    path.write_text(source)
    lib = Unit("t.lib", "t", (), (), source.split("\n", 1)[1], str(path), 2)
    units = prune_unreachable([lib, main("c() + e()")])
    text = emit("t", Plan(tier="balanced"), units, "shadertoy", "0")
    assert "b()" not in text and "d()" not in text and "B goes" not in text
    lines = source.split("\n")
    mapped = [
        (line, origin.line)
        for line, origin in zip(text.split("\n"), build_line_map(text, "out"), strict=False)
        if origin.file == str(path)
    ]
    assert [line for line, _ in mapped if line] == [
        "// A kept.",
        "float a() { return 1.0; }",
        "float c() {",
        "    return a() + 3.0;",
        "}",
        "float e() { return 5.0; }",
    ]
    assert all(lines[at - 1] == line for line, at in mapped)
    # A blank line stands where the source had one; none where it had none.
    assert "}\n\n// source:" in text and f"\n// source: {path}:9\n" in text
    assert "}\n// source: " + str(path) + ":13\nfloat e()" in text


@needs_glslang
def test_an_error_in_a_later_piece_is_reported_at_its_snippet_line(tmp_path: Path) -> None:
    source = (
        "float kept() { return 1.0; }\n"
        "float gone() { return 2.0; }\n"
        "float bad() {\n"
        "    return undefinedName;\n"  # line 4
        "}\n"
    )
    path = tmp_path / "bad.glsl"
    path.write_text(source)
    lib = Unit("t.bad", "t", (), (), source, str(path), 1)
    units = prune_unreachable([lib, main("kept() + bad()")])
    text = emit("t", Plan(tier="balanced"), units, "shadertoy", "0")
    assert "gone" not in text
    [diagnostic] = validate(text, "out.glsl")
    assert (diagnostic.file, diagnostic.line) == (str(path), 4)


def test_generated_pieces_take_no_marker() -> None:
    code = generated("scene.code", [], [], "float x() { return 1.0; }\nfloat y() { return 2.0; }\n")
    [unit, _] = prune_unreachable([code, main("y()")])
    assert unit.origin == GENERATED and unit.body == "float y() { return 2.0; }\n"
