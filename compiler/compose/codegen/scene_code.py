"""GLSL generated from the scene itself: its constants, its distance field, its materials, the
shading of a hit point and `mainImage`. Everything reusable lives in snippets; this is only the
scene-specific glue, and it calls slots only through their entry functions.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from glint.compiler.catalog.loader import glsl_float, glsl_value
from glint.compiler.compose.codegen.bounds import span_unit
from glint.compiler.compose.codegen.camera_path import path_unit
from glint.compiler.compose.codegen.field_code import ObjectCode, object_code
from glint.compiler.compose.codegen.knobs import UniformParam
from glint.compiler.compose.codegen.light_code import HIT_LIFT, LightCode, light_code
from glint.compiler.compose.codegen.trace_code import trace_unit
from glint.compiler.compose.codegen.user_geometry import (
    ALBEDO,
    DISTANCE,
    GEOMETRY_MATERIAL,
    MATERIAL,
    user_unit,
)
from glint.compiler.compose.units import Unit, generated
from glint.compiler.scene.model import (
    DirectionalLight,
    Material,
    PathCamera,
    Scene,
)
from glint.compiler.scene.values import comment_text


@dataclass
class SceneCode:
    defines: dict[str, str]  # light constants: name -> GLSL expression
    units: list[Unit]  # map, materials, shading, mainImage
    # the scene's values a page may set live (--params-as-uniforms): the lights' intensities,
    # the materials' roughness and metallic, the exposure; each is one of `defines`
    knobs: dict[str, UniformParam] = field(default_factory=dict)


def generate(
    scene: Scene, normal_in_uniform_flow: bool = False, tier: str | None = None
) -> SceneCode:
    """The scene's own code at `tier` (the scene's own by default). `normal_in_uniform_flow`
    computes the normal outside the hit branch, for normal variants built on screen-space
    derivatives."""
    tier = tier or scene.quality.tier
    lights = light_code(scene)
    materials = scene.used_materials()
    objects = [object_code(obj, i) for i, obj in enumerate(scene.objects)]
    units = [_map_unit(scene, objects)]
    if isinstance(scene.camera, PathCamera):
        units.append(path_unit(scene.camera))
    if any(code.name for code in objects):
        units.append(_objects_unit(objects))
    trace = trace_unit(scene.objects) if scene.geometry is None else None
    if trace is not None:  # pruned unless the plan takes an analytic variant
        units.append(trace)
    # where a bounded march need run: pruned unless the plan takes one
    field_bounds = scene.geometry.bounds if scene.geometry is not None else None
    units.append(span_unit(scene.objects, scene.geometry is not None, field_bounds))
    albedo_by_user = False
    if scene.geometry is not None:
        user = user_unit(scene.geometry, lights.defines, scene.bound_channels())
        units.append(user)
        albedo_by_user = ALBEDO in user.provides
    if scene.bound_channels():
        units.append(_pictures_unit(sorted(scene.bound_channels())))
    if len(materials) > 1:
        units.append(_material_index_unit(scene, materials, objects))
    values = material_values(scene, materials)
    units.append(surface_unit(scene, materials, albedo_by_user, values))
    # Translucency is lit by directional lights only; without one it has nothing to show.
    translucent = bool(lights.directional) and any(
        scene.materials[m].subsurface is not None for m in materials
    )
    if translucent:
        units.append(_subsurface_unit(scene, materials))
    emissive = any(scene.materials[m].emission is not None for m in materials)
    if emissive:
        units.append(_emission_unit(scene, materials))
    mirrored = scene.effects.reflections and tier in MIRROR_TIERS
    units.append(shade_unit(scene, lights, translucent, emissive, mirrored))
    if mirrored:
        units.append(_mirror_unit(scene))
    path = None  # how far the light from the hit point travels through the medium
    if scene.medium is not None:
        path = "t"
        if scene.medium.level is not None:
            units.append(_submerged_unit(scene.medium.level))
            path = "submerged(ro, rd, t)"
    # a shadow ray (and a mirror ray) starts from the lifted point
    lifted = HIT_LIFT in lights.requires or mirrored
    if scene.geometry is not None and scene.geometry.detail is not None:
        units.append(_detail_unit(scene.geometry.detail, scene.geometry.detail_strength))
    if lifted:
        units.append(_hit_lift_unit())
    units.append(_main_unit(scene, normal_in_uniform_flow, path, lifted))
    knobs = dict(lights.knobs)
    for material_knobs in values.values():
        knobs.update((knob.name, knob) for knob in material_knobs)
    knobs[EXPOSURE] = exposure_knob(scene)
    defines = dict(lights.defines)  # the lights' knobs are there already, within expressions
    for knob in knobs.values():
        defines.setdefault(knob.name, glsl_value(knob.default, knob.type))
    return SceneCode(defines=defines, units=units, knobs=knobs)


def _vec3(v: list[float]) -> str:
    return glsl_value(v, "vec3")


EXPOSURE = "EXPOSURE"


def exposure_knob(scene: Scene) -> UniformParam:
    """[post] exposure, which scales the linear colour before the tone map: five stops either
    way of 1, wider where the scene's own value lies outside."""

    value = scene.post.exposure
    return UniformParam(EXPOSURE, "float", value, min(1 / 32, value), max(32.0, value))


def material_values(scene: Scene, materials: list[str]) -> dict[str, list[UniformParam]]:
    """Per material, its albedo, roughness and (for a metal) metallic as named constants
    (MAT_<NAME>_ALBEDO, a linear RGB colour; MAT_<NAME>_ROUGHNESS, MAT_<NAME>_METALLIC in
    [0, 1]): knobs a page can turn."""

    out: dict[str, list[UniformParam]] = {}
    taken: set[str] = set()
    for name in materials:
        material = scene.materials[name]
        ident = "MAT_" + re.sub(r"[^A-Za-z0-9]", "_", name).upper()
        if ident in taken:  # two names that read the same in capitals
            ident += f"_{len(taken)}"
        taken.add(ident)
        albedo = [float(c) for c in material.albedo]
        knobs = [
            UniformParam(f"{ident}_ALBEDO", "vec3", albedo, 0.0, 1.0, control="color"),
            UniformParam(f"{ident}_ROUGHNESS", "float", material.roughness, 0.0, 1.0),
        ]
        if material.metallic > 0.0:
            knobs.append(UniformParam(f"{ident}_METALLIC", "float", material.metallic, 0.0, 1.0))
        out[name] = knobs
    return out


def _map_unit(scene: Scene, objects: list[ObjectCode]) -> Unit:
    lines = ["// The scene's signed distance: the union of its objects.", "float map(vec3 p) {"]
    requires = [name for code in objects for name in _called(code)]
    terms = [code.expression for code in objects]
    if scene.geometry is not None:
        terms.append(_user_distance(scene))
        requires.append(DISTANCE)
    for i, expr in enumerate(terms):
        lines.append(f"    float d = {expr};" if i == 0 else f"    d = min(d, {expr});")
    lines += ["    return d;", "}"]
    return generated("scene.map", ["map"], requires, "\n".join(lines) + "\n")


def _called(code: ObjectCode) -> list[str]:
    """What a line computing an object's distance calls: its own function, or the primitive
    written inline."""
    return [code.name] if code.name else code.requires


def _user_distance(scene: Scene) -> str:
    """The user's field, divided by its Lipschitz bound: a step of that length cannot cross
    the surface, so every march through `map` (hits, shadows, occlusion) stays correct."""
    assert scene.geometry is not None
    bound = scene.geometry.lipschitz
    return f"{DISTANCE}(p)" if bound == 1.0 else f"{DISTANCE}(p) / {glsl_float(bound)}"


def _objects_unit(objects: list[ObjectCode]) -> Unit:
    functions = [code for code in objects if code.name]
    names = [code.name for code in functions]
    requires = [name for code in functions for name in code.requires]
    body = "\n".join(code.function for code in functions)
    return generated("scene.objects", names, requires, body)


def _material_index_unit(scene: Scene, materials: list[str], objects: list[ObjectCode]) -> Unit:
    provides = ["materialAt"]
    lines = []
    if scene.geometry is not None and scene.geometry.materials:
        lines = _geometry_material_function(scene, materials)
        provides.append(GEOMETRY_MATERIAL)
    lines += [
        "// Index of the material of the object nearest to p.",
        "int materialAt(vec3 p) {",
    ]
    requires = [name for code in objects for name in _called(code)]
    candidates = [
        (code.expression, str(materials.index(obj.material)))  # type: ignore[arg-type]
        for obj, code in zip(scene.objects, objects, strict=True)
    ]
    if scene.geometry is not None:
        candidates.append((_user_distance(scene), _user_material(scene, materials)))
        requires.append(DISTANCE)
        if scene.geometry.materials:
            requires.append(MATERIAL)
    for i, (expr, index) in enumerate(candidates):
        if i == 0:
            lines += [f"    float best = {expr};", f"    int id = {index};"]
        else:
            lines += [
                f"    float d{i} = {expr};",
                f"    if (d{i} < best) {{ best = d{i}; id = {index}; }}",
            ]
    lines += ["    return id;", "}"]
    return generated("scene.materials", provides, requires, "\n".join(lines) + "\n")


def _user_material(scene: Scene, materials: list[str]) -> str:
    """The material index of the user's field at p: its one material, or geometryMaterial(p)
    (_geometry_material_function) when sceneMaterial returns ids."""
    geometry = scene.geometry
    assert geometry is not None
    if geometry.material is not None:
        return str(materials.index(geometry.material))
    return f"{GEOMETRY_MATERIAL}(p)"


def _geometry_material_function(scene: Scene, materials: list[str]) -> list[str]:
    """`geometryMaterial(p)`: sceneMaterial's id as the index of its material here; an id the
    scene does not list takes the first listed one's material."""
    assert scene.geometry is not None
    pairs = [(int(key), materials.index(name)) for key, name in scene.geometry.materials.items()]
    lines = [
        "// The material index of the user's field at p, from the id sceneMaterial returns.",
        f"int {GEOMETRY_MATERIAL}(vec3 p) {{",
        f"    int id = {MATERIAL}(p);",
    ]
    lines += [f"    if (id == {key}) return {index};" for key, index in pairs[1:]]
    return [*lines, f"    return {pairs[0][1]};", "}", ""]


def _albedo(material: Material, named: str | None = None) -> tuple[str, list[str]]:
    """The material's albedo as an expression (`named`: the constant that holds its colour)
    and what it requires."""
    base = named or _vec3(material.albedo)
    if material.albedo_texture is not None:
        scale = glsl_float(material.texture_scale)
        return f"{base} * picture{material.albedo_texture}(P, N, {scale})", [
            f"picture{material.albedo_texture}"
        ]
    if material.pattern == "checker":
        assert material.pattern_albedo is not None  # the scene model checks this
        return f"mix({base}, {_vec3(material.pattern_albedo)}, checker(P))", ["checker"]
    return base, []


def _pictures_unit(channels: list[int]) -> Unit:
    """`pictureN(P, N, scale)` for each channel a material reads: its picture sampled along the
    three axes (the picture repeats every `scale`) and blended by pattern.triplanar."""
    functions = []
    for unit in channels:
        sample = [f"texture(iChannel{unit}, P.{axes} / scale).rgb" for axes in ("zy", "xz", "xy")]
        functions.append(
            f"// The picture on iChannel{unit} wrapped onto the surface at P.\n"
            f"vec3 picture{unit}(vec3 P, vec3 N, float scale) {{\n"
            f"    return triplanar({sample[0]},\n"
            f"                     {sample[1]},\n"
            f"                     {sample[2]}, N);\n"
            "}\n"
        )
    names = [f"picture{unit}" for unit in channels]
    return generated("scene.pictures", names, ["triplanar"], "\n".join(functions))


def _by_material(bodies: list[list[str]]) -> tuple[list[str], list[str]]:
    """Function-body lines that run `bodies[i]` for material i (the last one as the default)
    and what they require: one material needs no lookup, more branch on `materialAt`."""
    if len(bodies) == 1:
        return [f"    {line}" for line in bodies[0]], []
    lines = ["    int id = materialAt(P);"]
    for index in range(len(bodies) - 1, 0, -1):
        lines += [f"    if (id == {index}) {{", *[f"        {x}" for x in bodies[index]], "    }"]
    return lines + [f"    {line}" for line in bodies[0]], ["materialAt"]


def surface_unit(
    scene: Scene,
    materials: list[str],
    albedo_by_user: bool,
    values: dict[str, list[UniformParam]] | None = None,
) -> Unit:
    """`surfaceAt`; `albedo_by_user`: the user's file defines sceneAlbedo; `values`: the named
    constants that hold each material's roughness and metallic (material_values), where the
    code reads them rather than literals."""
    requires = ["Surface", "makeSurface"]
    bodies = []
    procedural = _procedural_albedo_ids(scene) if albedo_by_user else {}
    for name in materials:
        material = scene.materials[name]
        named = {k.name.rsplit("_", 1)[1]: k.name for k in (values or {}).get(name, [])}
        albedo, needs = _albedo(material, named.get("ALBEDO"))
        requires += needs
        if name in procedural:  # the user's sceneAlbedo makes it from the material's own
            albedo = f"{ALBEDO}(P, {procedural[name]}, {albedo})"
            requires.append(ALBEDO)
        body, extra = _material_body(material, albedo, named)
        requires += extra
        bodies.append(body)
    branches, lookup = _by_material(bodies)
    lines = ["// The material at a hit point."]
    for channel in sorted(scene.bound_channels()):
        users = [m for m in materials if scene.materials[m].albedo_texture == channel]
        picture = scene.channels.get(str(channel))
        named = f"{comment_text(picture)}: " if picture else ""
        lines.append(
            f"// iChannel{channel}: bind a picture to it ({named}the albedo of "
            f"{', '.join(comment_text(u) for u in users)})."
        )
    lines.append("Surface surfaceAt(vec3 P, vec3 N, vec3 V) {")
    lines += [*branches, "}"]
    return generated("scene.surface", ["surfaceAt"], requires + lookup, "\n".join(lines) + "\n")


def _procedural_albedo_ids(scene: Scene) -> dict[str, int]:
    """The materials of the user's field whose albedo sceneAlbedo makes, with the id it is
    given (the material's id in [geometry.materials], 0 for the one [geometry] material)."""
    geometry = scene.geometry
    if geometry is None:
        return {}
    if geometry.material is not None:
        return {geometry.material: 0}
    ids: dict[str, int] = {}
    for key, name in geometry.materials.items():
        ids.setdefault(name, int(key))
    return ids


def _material_body(
    material: Material, albedo: str, named: dict[str, str] | None = None
) -> tuple[list[str], list[str]]:
    """The lines that build one material's Surface, and what they require beyond makeSurface:
    the metallic path and the diffuse roughness appear only for materials that have them."""
    metal = material.metallic > 0.0
    prelude = []
    if metal and (albedo.startswith(("mix(", ALBEDO)) or " * picture" in albedo):
        # a pattern or a picture: evaluate it once for both
        prelude, albedo = [f"vec3 albedo = {albedo};"], "albedo"
    named = named or {}
    roughness = named.get("ROUGHNESS", glsl_float(material.roughness))
    call = f"makeSurface(P, N, V, {albedo}, {roughness})"
    if not metal and material.diffuse_roughness is None:
        return [f"return {call};"], []
    lines = [*prelude, f"Surface s = {call};"]
    if metal:
        metallic = named.get("METALLIC", glsl_float(material.metallic))
        lines.append(f"applyMetallic(s, {albedo}, {metallic});")
    if material.diffuse_roughness is not None:
        lines.append(f"s.diffuseRoughness = {glsl_float(material.diffuse_roughness)};")
    return [*lines, "return s;"], ["applyMetallic"] if metal else []


def _subsurface_unit(scene: Scene, materials: list[str]) -> Unit:
    """`subsurfaceAt(P)`: the scattering colour and phase asymmetry g of the material at P;
    zero colour for opaque materials."""
    bodies = []
    for name in materials:
        material = scene.materials[name]
        color = _vec3(material.subsurface or [0.0, 0.0, 0.0])
        bodies.append([f"return vec4({color}, {glsl_float(material.subsurface_g)});"])
    branches, lookup = _by_material(bodies)
    lines = [
        "// Subsurface scattering colour (rgb) and phase asymmetry g (w) of the material at P.",
        "vec4 subsurfaceAt(vec3 P) {",
        *branches,
        "}",
    ]
    return generated("scene.subsurface", ["subsurfaceAt"], lookup, "\n".join(lines) + "\n")


def _translucency(ident: str) -> str:
    """Light of one directional light that crosses the body and scatters toward the eye:
    colour × radiance × transmittance toward L × phase(cos θ), θ between the light's direction
    of travel (−L) and the way to the eye (V), so a back-lit body glows for g > 0."""
    return (
        f"sss.rgb * {ident}_COLOR * subsurface(s.P, {ident}_DIR)"
        f" * phase(-dot({ident}_DIR, s.V), sss.w)"
    )


def _emission_unit(scene: Scene, materials: list[str]) -> Unit:
    """`emissionAt(P)`: the light the material at P gives off itself (0 for most)."""
    bodies = [
        [f"return {_vec3(scene.materials[name].emission or [0.0, 0.0, 0.0])};"]
        for name in materials
    ]
    branches, lookup = _by_material(bodies)
    lines = ["// Light the material at P gives off itself.", "vec3 emissionAt(vec3 P) {"]
    lines += [*branches, "}"]
    return generated("scene.emission", ["emissionAt"], lookup, "\n".join(lines) + "\n")


# The tiers whose smooth surfaces reflect the scene when effects.reflections is on, and the
# roughness below which they do (fading in from it to 0).
MIRROR_TIERS = ("balanced", "reference")
MIRROR_ROUGHNESS = 0.3
MIRROR_UNIT = "scene.mirror"


def _mirror_unit(scene: Scene) -> Unit:
    """`shade` with one mirror bounce: where a smooth surface's mirror ray meets the scene,
    what it sees there (shadeDirect: lit, emission included, not reflecting again) takes the
    place of the environment in its reflection, weighted by Fresnel at N·V (the split sum's
    weight on a mirror)."""
    environment = scene.environment is not None and scene.environment.reflection
    replaced = " - environment(R)" if environment else ""
    rough = glsl_float(MIRROR_ROUGHNESS)
    body = f"""// effects.reflections: one mirror bounce through the scene for smooth surfaces.
vec3 shade(Surface s) {{
    vec3 color = shadeDirect(s);
    float mirror = 1.0 - smoothstep(0.0, {rough}, s.roughness);
    if (mirror > 0.0) {{
        vec3 R = reflect(-s.V, s.N);
        vec3 origin = s.P + s.N * ({HIT_LIFT} + 0.02);
        float t = raymarch(origin, R);
        if (t > 0.0) {{
            vec3 Q = origin + t * R;
            vec3 seen = shadeDirect(surfaceAt(Q, calcNormal(Q), -R));
            color += mirror * fresnel(s.f0, s.NoV) * (seen{replaced});
        }}
    }}
    return color;
}}
"""
    requires = ["Surface", "shadeDirect", "raymarch", "surfaceAt", "calcNormal", "fresnel"]
    requires += [HIT_LIFT] + (["env"] if environment else [])
    why = [("raymarch", "effects.reflections: smooth surfaces trace a mirror ray"),
           ("fresnel", "effects.reflections weighs what a mirror sees by Fresnel")]  # fmt: skip
    return generated(MIRROR_UNIT, ["shade"], requires, body, why=why)


def shade_unit(
    scene: Scene,
    lights: LightCode,
    translucent: bool,
    emissive: bool = False,
    mirrored: bool = False,
) -> Unit:
    """`shade(s)`: the light a surface point sends to the eye; `mirrored`: named shadeDirect,
    under the `shade` that adds a mirror bounce (_mirror_unit)."""
    name = "shadeDirect" if mirrored else "shade"
    lines = ["// Light arriving at the eye from a surface point.", f"vec3 {name}(Surface s) {{"]
    requires = ["Surface", *lights.requires]
    why = list(lights.why)
    light_calls = lights.calls
    # the lights AO darkens: those whose term takes the occlusion (fill and environment lights)
    occluded = [label for label, call in zip(lights.labels, light_calls, strict=True)
                if "occlusion" in call]  # fmt: skip
    reflection = scene.environment is not None and scene.environment.reflection
    if reflection:
        why.append(("environmentLight", "environment.reflection = true"))
        occluded.append("the environment reflection")
    occlusion = "1.0"
    if scene.effects.ao and occluded:
        lines.append("    float occlusion = ambientOcclusion(s.P, s.N);")
        requires.append("ambientOcclusion")
        why.append(("ambientOcclusion", f"effects.ao darkens {', '.join(occluded)}"))
        occlusion = "occlusion"
    lines.append("    vec3 color = vec3(0.0);")
    for call in light_calls:
        lines.append(f"    color += {call.replace('occlusion', occlusion)};")
    if translucent:
        lines.append("    vec4 sss = subsurfaceAt(s.P);")
        lines += [f"    color += {_translucency(ident)};" for ident in lights.directional]
        requires += ["subsurfaceAt", "subsurface", "phase"]
        material = next(
            m for m in scene.used_materials() if scene.materials[m].subsurface is not None
        )
        first = lights.labels[next(i for i, light in enumerate(scene.lights)
                                   if isinstance(light, DirectionalLight))]  # fmt: skip
        reason = f"material {material!r} has subsurface, lit by {first}"
        why += [("subsurface", reason), ("phase", reason)]
    if reflection:
        lines.append(f"    color += environmentLight(s, {occlusion});")
        requires.append("environmentLight")
    if emissive:
        lines.append("    color += emissionAt(s.P);")
        requires.append("emissionAt")
        material = next(m for m in scene.used_materials() if scene.materials[m].emission)
        why.append(("emissionAt", f"material {material!r} has emission"))
    lines += ["    return color;", "}"]
    return generated("scene.shade", [name], requires, "\n".join(lines) + "\n", why=why)


def _submerged_unit(level: float) -> Unit:
    """`submerged(ro, rd, t)`: how much of the ray's first t units lies below the water."""
    y = glsl_float(level)
    body = f"""// Length of the ray ro + u·rd, 0 <= u <= t, below the water level y = {y}.
float submerged(vec3 ro, vec3 rd, float t) {{
    float start = ro.y - {y};
    float end = start + t * rd.y;
    if (start >= 0.0 && end >= 0.0) return 0.0;
    if (start < 0.0 && end < 0.0) return t;
    // The ray crosses the level once, at u = −start / rd.y (rd.y is not 0: the ends differ).
    float crossing = -start / rd.y;
    return start < 0.0 ? crossing : t - crossing;
}}
"""
    return generated("scene.submerged", ["submerged"], [], body)


DETAIL_NORMAL = "detailNormal"


def _detail_unit(function: str, strength: float) -> Unit:
    """`detailNormal(P, N)`: the normal of the surface raised by the user's detail height
    along N (never marched: only shading sees it). A raised surface tilts against the height's
    gradient along the surface: N − (g − (g·N) N), g by central differences."""
    k = glsl_float(strength / 2e-3)
    body = f"""// [geometry] detail: the normal of the surface raised by {function}(p) along N.
vec3 {DETAIL_NORMAL}(vec3 P, vec3 N) {{
    vec2 e = vec2(1e-3, 0.0);
    vec3 g = vec3({function}(P + e.xyy) - {function}(P - e.xyy),
                  {function}(P + e.yxy) - {function}(P - e.yxy),
                  {function}(P + e.yyx) - {function}(P - e.yyx)) * {k};
    return normalize(N - (g - dot(g, N) * N));
}}
"""
    return generated("scene.detail", [DETAIL_NORMAL], [function], body)


def _hit_lift_unit() -> Unit:
    """The global that carries the march's tolerance at the hit to the shadow rays."""
    body = (
        "// How far the march may have stopped from the surface at this pixel's hit\n"
        "// (marchTolerance): shadow rays start that far out along the normal.\n"
        f"float {HIT_LIFT} = 0.0;\n"
    )
    return generated("scene.hit_lift", [HIT_LIFT], [], body)


def _main_unit(
    scene: Scene, normal_in_uniform_flow: bool, medium_path: str | None = None, lifted: bool = False
) -> Unit:
    """`mainImage`; `lifted`: shadow rays start from the point lifted by hitLift, which it sets."""
    requires = [
        "cameraRay", "background", "raymarch", "shade", "surfaceAt", "calcNormal",
        "outputTransfer", "tonemap",
    ]  # fmt: skip
    why = [
        ("cameraRay", f"camera.type = {scene.camera.type!r}"),
        ("raymarch", "every pixel marches its ray to the first surface"),
        ("calcNormal", "shading needs the surface normal"),
        ("background", "rays that hit nothing show the background"),
        ("tonemap", f"post.tonemap = {scene.post.tonemap!r}"),
        ("outputTransfer", f"post.output = {scene.post.output!r}"),
    ]
    # The medium lies between the eye and the surfaces; the background is outside it.
    through = ""
    if medium_path is not None:
        kind = "water" if "submerged" in medium_path else "fog"
        why.append(("medium", f"[medium] ({kind})"))
        requires.append("medium")
        requires += ["submerged"] if "submerged" in medium_path else []
        through = f"        color = medium(color, {medium_path});\n"
    # The march stops up to marchTolerance(t) from the surface, on either side: shadow rays
    # start that far out along the normal (HIT_LIFT), or a hit accepted that far off a concave
    # rim shadows itself (dark hairlines). Only shadows: AO and the rest read the point itself.
    lift = ""
    if lifted:
        lift = f"        {HIT_LIFT} = marchTolerance(t);\n"
        requires += ["marchTolerance", HIT_LIFT]
        why.append(("marchTolerance", "shadow rays start clear of where the march stopped"))
    # A background shown as given skips exposure and the tone map: only what the rays hit
    # goes through them.
    exposed = "tonemap(color * EXPOSURE)"
    if not scene.background.tonemap:
        through += f"        color = {exposed};\n"
    geometry = scene.geometry
    normal = "calcNormal(P)"
    detailed = ""
    if geometry is not None and geometry.detail is not None:
        normal = f"{DETAIL_NORMAL}(P, calcNormal(P))"
        detailed = f"    N = {DETAIL_NORMAL}(P, N);\n"
        requires.append(DETAIL_NORMAL)
        why.append((DETAIL_NORMAL, f"geometry.detail = {geometry.detail!r}"))
    if not normal_in_uniform_flow:
        hit = f"""    if (t > 0.0) {{
        vec3 P = ro + t * rd;
{lift}        color = shade(surfaceAt(P, {normal}, -rd));
{through}    }}
"""
    else:
        # Screen-space derivatives are undefined inside a branch that neighbouring pixels may
        # not take, so a derivative normal is computed by every pixel: rays that miss use a
        # far point, which keeps the 2×2 blocks at the horizon from mixing in the eye.
        # MARCH_FAR is the raymarch variant's parameter (written by the parameter block).
        # A derivative normal's sign depends on the runner's dFdy convention (wgpu-shadertoy
        # flips fragCoord's y and not dFdy's): the first surface a ray meets faces the eye.
        hit = f"""    vec3 P = ro + (t > 0.0 ? t : MARCH_FAR) * rd;
    vec3 N = calcNormal(P);
    N = faceforward(N, rd, N);
{detailed}    if (t > 0.0) {{
{lift}        color = shade(surfaceAt(P, N, -rd));
{through}    }}
"""
    setup = ""
    if geometry is not None and geometry.setup is not None:
        setup = f"    {geometry.setup}();\n"
        requires.append(geometry.setup)
        why.append((geometry.setup, f"geometry.setup = {geometry.setup!r}"))
    cast = (
        f"{setup}"
        "    vec3 ro;\n"
        "    vec3 rd;\n"
        "    cameraRay(fragCoord, ro, rd);\n"
        "    vec3 color = background(rd);\n"
        "    float t = raymarch(ro, rd);\n"
        f"{hit}"
    )
    display = exposed if scene.background.tonemap else "color"
    aa = scene.quality.aa
    if aa == 1:
        body = (
            "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
            f"{cast}"
            f"    color = outputTransfer({display});\n"
            "    fragColor = vec4(color, 1.0);\n"
            "}\n"
        )
        return generated("scene.main", ["mainImage"], requires, body, why=why)
    why.append(("pixelColor", f"quality.aa = {aa}: {aa * aa} rays per pixel"))
    body = (
        "// The tone-mapped colour seen along the ray through fragCoord.\n"
        "vec3 pixelColor(vec2 fragCoord) {\n"
        f"{cast}"
        f"    return {display};\n"
        "}\n"
        "\n"
        "// quality.aa: the mean of a grid of rays spread evenly over the pixel, taken after the\n"
        "// tone map (a bright edge then blends as the eye sees it) and before the transfer.\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    vec3 sum = vec3(0.0);\n"
        f"    for (int i = 0; i < {aa}; i++) {{\n"
        f"        for (int j = 0; j < {aa}; j++) {{\n"
        f"            sum += pixelColor(fragCoord + (vec2(i, j) + 0.5) / {aa}.0 - 0.5);\n"
        "        }\n"
        "    }\n"
        f"    fragColor = vec4(outputTransfer(sum / {aa * aa}.0), 1.0);\n"
        "}\n"
    )
    return generated("scene.main", ["pixelColor", "mainImage"], requires, body, why=why)
