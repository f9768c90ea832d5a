"""GLSL generated for a mesh scene: per material, the interface and `main` of a vertex and a
fragment shader around the scene code that raymarched scenes use too (`surfaceAt`, `shade`).

Where the light is computed is the material's shading mode:

- phong: the vertex shader places the vertex and passes its world position and normal; the
  fragment shader lights each pixel with the interpolated normal;
- gouraud: the vertex shader lights the vertex (the catalog's diffuse and specular variants run
  there unchanged) and passes the linear colour; the fragment shader tone maps it;
- flat: the fragment shader takes the face's normal from the screen-space derivatives of the
  world position, turned toward the eye.

There is no distance field, so nothing here marches: no shadow rays, no SDF occlusion, no
subsurface probe (`lit_scene` turns them off and `ignored` says so).
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import glsl_float
from glint.compiler.compose.codegen.light_code import light_code
from glint.compiler.compose.codegen.scene_code import EXPOSURE, shade_unit, surface_unit
from glint.compiler.compose.units import Unit, generated
from glint.compiler.scene.model import Scene
from glint.compiler.target.mesh import ATTRIBUTES, UNIFORMS

VERTEX_MAIN = "mesh.vertex"
FRAGMENT_MAIN = "mesh.fragment"


@dataclass
class MeshCode:
    defines: dict[str, str]  # light constants: name -> GLSL expression
    vertex: list[Unit]  # the vertex stage's own code and what it calls
    fragment: list[Unit]


def lit_scene(scene: Scene, material: str | None = None) -> Scene:
    """The scene as one material's program sees it: only that material's meshes (all of them
    for None), and nothing that needs a distance field (shadows, SDF occlusion, subsurface
    probing)."""
    lights = [
        light.model_copy(update={"shadow": False}) if getattr(light, "shadow", False) else light
        for light in scene.lights
    ]
    materials = {
        name: m.model_copy(update={"subsurface": None}) for name, m in scene.materials.items()
    }
    objects = [obj for obj in scene.objects if material in (None, obj.material)]
    return scene.model_copy(
        update={
            "lights": lights,
            "materials": materials,
            "objects": objects,
            "effects": scene.effects.model_copy(update={"ao": False}),
        }
    )


def ignored(scene: Scene) -> list[str]:
    """What the scene asks for that has no effect on meshes, each with the key."""
    notes = [
        f"lights[{i}].shadow = true: no effect on meshes (no distance field to trace)"
        for i, light in enumerate(scene.lights)
        if getattr(light, "shadow", False)
    ]
    if scene.effects.ao:
        notes.append("effects.ao = true: no effect on meshes (no distance field to probe)")
    notes += [
        f"materials.{name}.subsurface: no effect on meshes (no distance field to probe)"
        for name in scene.used_materials()
        if scene.materials[name].subsurface is not None
    ]
    return notes


def mesh_code(scene: Scene, material: str) -> MeshCode:
    """The two stages of `material`'s program; `scene` is `lit_scene(scene, material)`."""
    shading = scene.shading_of(material)
    lights = light_code(scene)
    lit = [surface_unit(scene, [material], False), shade_unit(scene, lights, False)]
    post = [
        ("tonemap", f"post.tonemap = {scene.post.tonemap!r}"),
        ("outputTransfer", f"post.output = {scene.post.output!r}"),
    ]
    if shading == "gouraud":
        vertex = [*lit, _vertex_main(lit=True)]
        fragment = [_fragment_main("vColor", [], post)]
    else:
        vertex = [_vertex_main(lit=False, normal=shading == "phong")]
        fragment = [*lit, _fragment_main(None, _fragment_normal(shading), post)]
    defines = {**lights.defines, EXPOSURE: glsl_float(scene.post.exposure)}
    return MeshCode(defines, vertex, fragment)


def _declarations(kind: str, pairs: list[tuple[str, str]]) -> list[str]:
    return [f"{kind} {ty} {name};" for ty, name in pairs]


def _uniform_lines() -> list[str]:
    return [f"uniform {ty} {name};  // {what}" for ty, name, what in UNIFORMS]


def _vertex_main(lit: bool, normal: bool = True) -> Unit:
    """The vertex stage's interface and main: place the vertex; light it (gouraud) or pass
    what the fragment stage lights with."""
    outs = [("vec3", "vColor")] if lit else [("vec3", "vWorldPosition")]
    if not lit and normal:
        outs.append(("vec3", "vNormal"))
    lines = [
        "// three.js RawShaderMaterial's attributes and uniforms (normalMatrix in world space).",
        *_declarations("in", list(ATTRIBUTES)),
        *_uniform_lines(),
        *_declarations("out", outs),
        "",
        "void main() {",
        "    vec4 world = modelMatrix * vec4(position, 1.0);",
    ]
    requires = ["shade", "surfaceAt"] if lit else []
    why = [("shade", "gouraud shading lights each vertex")] if lit else []
    if lit:
        lines += [
            "    vec3 P = world.xyz;",
            "    vec3 N = normalize(normalMatrix * normal);",
            "    vColor = shade(surfaceAt(P, N, normalize(cameraPosition - P)));",
        ]
    else:
        lines.append("    vWorldPosition = world.xyz;")
        if normal:
            lines.append("    vNormal = normalMatrix * normal;")
    lines += ["    gl_Position = projectionMatrix * viewMatrix * world;", "}"]
    return generated(VERTEX_MAIN, ["main"], requires, "\n".join(lines) + "\n", why=why)


def _fragment_normal(shading: str) -> list[str]:
    """The lines that set N at the pixel."""
    if shading == "phong":
        return ["vec3 N = normalize(vNormal);"]
    # Two vectors across the triangle, one pixel apart on screen: their cross product is the
    # face's normal. Its sign follows the winding and the runner's dFdy, so turn it to the eye.
    return [
        "vec3 N = normalize(cross(dFdx(P), dFdy(P)));",
        "N = faceforward(N, -V, N);",
    ]


def _fragment_main(color_in: str | None, normal: list[str], post: list[tuple[str, str]]) -> Unit:
    """The fragment stage's interface and main: light the pixel (phong, flat) or take the
    interpolated colour (gouraud); then tone map and output."""
    ins = [("vec3", color_in)] if color_in else [("vec3", "vWorldPosition")]
    if normal and "vNormal" in normal[0]:
        ins.append(("vec3", "vNormal"))
    lines = [
        *_declarations("in", ins),
        *([] if color_in else ["uniform vec3 cameraPosition;  // the eye, in world space"]),
        "out vec4 fragColor;",
        "",
        "void main() {",
    ]
    requires = ["tonemap", "outputTransfer"]
    why = list(post)
    if color_in:
        lines.append(f"    vec3 color = {color_in};")
    else:
        lines += ["    vec3 P = vWorldPosition;", "    vec3 V = normalize(cameraPosition - P);"]
        lines += [f"    {line}" for line in normal]
        lines.append("    vec3 color = shade(surfaceAt(P, N, V));")
        requires += ["shade", "surfaceAt"]
        why.insert(0, ("shade", "phong and flat shading light each pixel"))
    lines += ["    fragColor = vec4(outputTransfer(tonemap(color * EXPOSURE)), 1.0);", "}"]
    return generated(FRAGMENT_MAIN, ["main"], requires, "\n".join(lines) + "\n", why=why)


def background_unit(scene: Scene) -> Unit:
    """`mainImage` of the background program, drawn on a full-screen triangle before the
    meshes: the raymarched scenes' sky for the rays that hit nothing, with their camera."""
    body = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    vec3 ro;\n"
        "    vec3 rd;\n"
        "    cameraRay(fragCoord, ro, rd);\n"
        "    fragColor = vec4(outputTransfer(tonemap(background(rd) * EXPOSURE)), 1.0);\n"
        "}\n"
    )
    why = [
        ("cameraRay", f"camera.type = {scene.camera.type!r}"),
        ("background", "pixels no mesh covers show the background"),
        ("tonemap", f"post.tonemap = {scene.post.tonemap!r}"),
        ("outputTransfer", f"post.output = {scene.post.output!r}"),
    ]
    requires = ["cameraRay", "background", "tonemap", "outputTransfer"]
    return generated("mesh.background", ["mainImage"], requires, body, why=why)
