"""Lighting rules L001-L008: a positive and a negative case for each (the seeds' known defects
among the positives), L002's unsafe fix, fixed shaders that glslang accepts, idempotent
fixing, and silence on the valid corpora and the catalog's own lighting code."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from glint.compiler.bench.scenes import template_source
from glint.compiler.target.glslang import validate
from glint.lint.options import Options
from glint.lint.rules import all_rules, rule_doc
from glint.lint.runner import lint_source, lint_text

FAST = Options(select=["L"], glslang=False)
CORPORA = Path(__file__).resolve().parent.parent / "corpus"
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)
CODES = ["L001", "L002", "L003", "L004", "L005", "L006", "L007", "L008"]


def found(text: str, code: str | None = None) -> list[tuple[str, int]]:
    return [(f.code, f.line) for f in lint_source(text, "x.glsl", FAST)
            if code is None or f.code == code]  # fmt: skip


def image(body: str, head: str = "") -> str:
    return f"{head}void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n{body}\n}}\n"


@pytest.mark.parametrize("code", CODES)
def test_rule_is_documented(code: str) -> None:
    rule = all_rules()[code]
    doc = rule_doc(rule)
    assert all(doc[k] for k in ("summary", "why", "example", "fix"))
    assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", rule.name)
    assert rule.category == "lighting" and rule.severity == "warning"


# --- L001 -----------------------------------------------------------------------------------

SEED_003 = """float shade(vec3 PixelNormal, vec3 LightDir, float SpecularColor) {
    float NdotL = max( 0.0, dot( PixelNormal, LightDir ) );
    float fresnelFactor = SpecularColor + ( 1.0 - SpecularColor ) * pow( ( 1.0 - NdotL ), 5.0 );
    return fresnelFactor;
}
"""


def test_l001_seed_003_fresnel_with_n_dot_l() -> None:
    assert found(SEED_003) == [("L001", 3)]
    message = lint_source(SEED_003, "x.glsl", FAST)[0].message
    assert "N·L" in message and "V·H" in message


def test_l001_named_fresnel_fed_n_dot_h() -> None:
    src = """vec3 F_Schlick(vec3 f0, float u) { return f0 + (1.0 - f0) * pow(1.0 - u, 5.0); }
vec3 spec(vec3 n, vec3 l, vec3 v, vec3 f0) {
    vec3 h = normalize(l + v);
    return F_Schlick(f0, max(dot(n, h), 0.0));
}
"""
    assert found(src) == [("L001", 4)]


def test_l001_v_dot_h_l_dot_h_and_n_dot_v_are_right() -> None:
    src = """vec3 fresnelSchlick(vec3 f0, float c) { return f0 + (1.0 - f0) * pow(1.0 - c, 5.0); }
vec3 spec(vec3 n, vec3 l, vec3 v, vec3 f0) {
    vec3 h = normalize(l + v);
    float dotLH = clamp(dot(l, h), 0.0, 1.0);
    float f = pow(1.0 - dotLH, 5.0);
    return fresnelSchlick(f0, dot(v, h)) + fresnelSchlick(f0, max(dot(n, v), 0.0)) + f;
}
"""
    assert found(src) == []


def test_l001_burley_diffuse_pairs_n_dot_l_with_n_dot_v() -> None:
    src = """float F_Schlick(float f0, float f90, float u) {
    return f0 + (f90 - f0) * pow(1.0 - u, 5.0);
}
float scatter(float NoL, float NoV, float f90) {
    return F_Schlick(1.0, f90, NoL) * F_Schlick(1.0, f90, NoV);
}
float Fd_Burley(float NoL, float NoV, float f90) {
    float l = pow(1.0 - NoL, 5.0);
    return l;
}
"""
    assert found(src) == []


# --- L002 -----------------------------------------------------------------------------------

UNCLAMPED = """vec3 shade(vec3 n, vec3 l, vec3 albedo) {
    vec3 col = albedo * dot(n, l);
    float ndl = dot(n, l);
    col += albedo * ndl * 0.5;
    return col;
}
float lambert(vec3 n, vec3 l) { return dot(n, l); }
"""


def test_l002_reports_unclamped_cosines_in_colour_terms() -> None:
    assert found(UNCLAMPED) == [("L002", 2), ("L002", 4), ("L002", 7)]


def test_l002_uses_the_model_range_a_cosine_of_positive_vectors_is_not_negative() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord, 1.0));\n"
        "    vec3 l = normalize(vec3(1.0));\n"
        "    vec3 col = vec3(0.8) * dot(n, l);\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);"
    )
    assert found(src) == []


def test_l002_clamped_guarded_and_half_lambert_are_fine() -> None:
    src = """vec3 shade(vec3 n, vec3 l, vec3 v, vec3 albedo) {
    vec3 col = albedo * max(dot(n, l), 0.0);
    col += albedo * clamp(dot(n, v), 0.0, 1.0);
    float hl = dot(n, l) * 0.5 + 0.5;
    col += albedo * hl;
    float ndl = dot(n, l);
    if (ndl <= 0.0) return col;
    return col + albedo * ndl;
}
float facing(vec3 n, vec3 v) { return dot(n, v); }
"""
    assert found(src) == []


def test_l002_unsafe_fix_clamps_direct_dot_products() -> None:
    result = lint_text(UNCLAMPED, "x.glsl", FAST, fix=True, unsafe_fixes=True)
    assert "vec3 col = albedo * max(dot(n, l), 0.0);" in result.text
    assert "return max(dot(n, l), 0.0);" in result.text
    assert [f.code for f in result.findings] == ["L002"]  # the local `ndl` has no fix
    assert lint_text(UNCLAMPED, "x.glsl", FAST, fix=True).text == UNCLAMPED  # unsafe only
    again = lint_text(result.text, "x.glsl", FAST, fix=True, unsafe_fixes=True)
    assert again.text == result.text


@needs_glslang
def test_l002_fixed_shader_validates() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 l = normalize(vec3(-1.0, 0.5, -0.3));\n"
        "    vec3 col = vec3(0.8) * dot(n, l);\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);"
    )
    result = lint_text(src, "x.glsl", FAST, fix=True, unsafe_fixes=True)
    assert "max(dot(n, l), 0.0)" in result.text
    assert [d for d in validate(result.text, "x.glsl", "shadertoy") if d.severity == "error"] == []


# --- L003 -----------------------------------------------------------------------------------

GGX = """#define PI 3.14159265
float D_GGX(float NoH, float a) {
    float a2 = a * a;
    float f = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (PI * f * f);
}
float V_SmithGGX(float NoV, float NoL, float roughness) {
    float a = roughness * roughness;
    return 0.5 / (NoV * (1.0 - a) + NoL * (1.0 - a) + a);
}
"""


def test_l003_squared_twice_and_not_at_all() -> None:
    src = (
        GGX
        + """float spec(float NoH, float NoV, float NoL, float roughness) {
    float r = max(roughness, 0.045);
    float a = r * r;
    float twice = D_GGX(NoH, a * a);
    float none = D_GGX(NoH, roughness);
    float alphaToRoughness = V_SmithGGX(NoV, NoL, a);
    return twice + none + alphaToRoughness;
}
"""
    )
    assert found(src) == [("L003", 14), ("L003", 15), ("L003", 16)]
    messages = [f.message for f in lint_source(src, "x.glsl", FAST)]
    assert "squared once too often" in messages[0] and "not squared" in messages[1]


def test_l003_consistent_powers_and_unknown_arguments_are_fine() -> None:
    src = (
        GGX
        + """float spec(float NoH, float NoV, float NoL, float roughness, float k) {
    float r = clamp(roughness, 0.045, 1.0);
    float alpha = r * r;
    return D_GGX(NoH, alpha) * V_SmithGGX(NoV, NoL, r) * D_GGX(NoH, k) * D_GGX(NoH, 0.5);
}
"""
    )
    assert found(src) == []


# --- L004 -----------------------------------------------------------------------------------

BLINN = """#define PI 3.14159265
vec3 fresnel(vec3 f0, float VoH) { return f0 + (1.0 - f0) * pow(1.0 - VoH, 5.0); }
vec3 spec(vec3 n, vec3 l, vec3 v, vec3 f0, float shininess) {
    vec3 h = normalize(l + v);
    float NoH = max(dot(n, h), 0.0);
    return fresnel(f0, max(dot(v, h), 0.0)) * LOBE;
}
"""


def test_l004_unnormalized_blinn_phong_next_to_fresnel() -> None:
    src = BLINN.replace("LOBE", "pow(NoH, shininess)")
    assert found(src) == [("L004", 6)]


def test_l004_normalized_lobe_or_no_pbr_term_is_fine() -> None:
    normalized = "(shininess + 8.0) / (8.0 * PI) * pow(NoH, shininess)"
    assert found(BLINN.replace("LOBE", normalized)) == []
    alone = """float spec(vec3 n, vec3 l, vec3 v) {
    vec3 halfDir = normalize(l + v);
    return pow(max(dot(n, halfDir), 0.0), 32.0);
}
"""
    assert found(alone) == []


def test_l002_wrap_lighting_and_projections_stay_signed() -> None:
    body = (
        "    vec3 N = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 L = normalize(vec3(1.0));\n"
        "    float dn = fragCoord.x * 0.01;\n"
        "    float nl = dot(N, L);\n"
        "    vec3 t = L - N * nl;\n"
        "    vec3 wrap = vec3(1.0) * (0.6 + dn * dot(N, L) * 0.4);\n"
        "    vec3 raw = vec3(0.8) * dn * dot(N, L);\n"
        "    fragColor = vec4(wrap + raw + t, 1.0);"
    )
    assert found(image(body), "L002") == [("L002", 8)]


def test_l004_a_lobe_or_fresnel_that_is_never_used_is_not_reported() -> None:
    head = "vec3 fresnelSchlick(float c, vec3 f0) { return f0 + (1.0 - f0) * pow(1.0 - c, 5.0); }\n"
    body = (
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 h = normalize(vec3(0.2, 0.3, 1.0));\n"
        "    vec3 fres = fresnelSchlick(dot(n, h), vec3(0.04));\n"
        "    float spec = pow(max(dot(n, h), 0.0), 20.0);\n"
        "    fragColor = vec4(OUT, 1.0);"
    )
    assert found(image(body.replace("OUT", "fres * spec"), head), "L004") == [("L004", 6)]
    assert found(image(body.replace("OUT", "n * 0.2"), head), "L004") == []


# --- L005 / L006 / L007 ---------------------------------------------------------------------

LIT = (
    "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
    "    vec3 l = normalize(vec3(1.0));\n"
    "    vec3 col = vec3(0.8) * max(dot(n, l), 0.0);\n"
)


def test_l005_lit_shader_without_gamma() -> None:
    assert found(image(LIT + "    fragColor = vec4(col, 1.0);")) == [("L005", 5)]


def test_l005_gamma_sqrt_srgb_function_or_2d_art_are_fine() -> None:
    assert found(image(LIT + "    fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);")) == []
    assert found(image(LIT + "    fragColor = vec4(sqrt(col), 1.0);")) == []
    srgb = "vec3 linearToSrgb(vec3 c) { return mix(c * 12.92, c, step(0.5, c)); }\n"
    assert found(image(LIT + "    fragColor = vec4(linearToSrgb(col), 1.0);", srgb)) == []
    art = image("    vec2 uv = fragCoord / iResolution.xy;\n    fragColor = vec4(uv, 0.5, 1.0);")
    assert found(art) == []


def test_l006_gamma_applied_twice() -> None:
    head = "vec3 toSRGB(vec3 c) { return pow(c, vec3(1.0 / 2.2)); }\n"
    src = image(
        LIT + "    col = toSRGB(col);\n    col = col * 0.9;\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);",
        head,
    )
    assert found(src) == [("L006", 8)]
    nested = image(LIT + "    fragColor = vec4(sqrt(pow(col, vec3(1.0 / 2.2))), 1.0);")
    assert found(nested) == [("L006", 5)]


def test_l006_one_encoding_is_fine() -> None:
    head = "vec3 toSRGB(vec3 c) { return pow(c, vec3(1.0 / 2.2)); }\n"
    src = image(
        LIT + "    vec3 shown = toSRGB(col);\n    col = col * 0.5;\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)) + shown * 0.0, 1.0);",
        head,
    )
    assert found(src) == []


def test_l007_bright_light_without_tonemap() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 lig = normalize(vec3(1.0));\n"
        "    float dif = clamp(dot(n, lig), 0.0, 1.0);\n"
        "    vec3 col = 2.0 * vec3(0.8) * dif;\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);"
    )
    assert found(src) == [("L007", 6)]


def test_l007_two_lights_summed_without_tonemap() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 sunDir = normalize(vec3(1.0));\n"
        "    vec3 col = vec3(0.0);\n"
        "    col += vec3(0.9, 0.8, 0.7) * max(dot(n, sunDir), 0.0);\n"
        "    col += vec3(0.2, 0.3, 0.5) * max(dot(n, vec3(0.0, 1.0, 0.0)), 0.0);\n"
        "    col += vec3(0.5) * max(dot(n, -sunDir), 0.0);\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);"
    )
    assert found(src) == [("L007", 8)]


def test_l007_normalized_highlight_reaches_above_one() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 h = normalize(vec3(0.2, 0.3, 1.0));\n"
        "    float NdotH = max(dot(n, h), 0.0);\n"
        "    float spec = pow(NdotH, 64.0) * (64.0 + 8.0) / (8.0 * PI);\n"
        "    fragColor = vec4(pow(vec3(spec), vec3(0.4545)), 1.0);",
        "const float PI = 3.14159265;\n",
    )
    assert found(src) == [("L007", 7)]
    assert "2.86" in lint_source(src, "x.glsl", FAST)[0].message


def test_l007_bright_radiance_divided_by_pi_stays_below_one() -> None:
    src = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 l = normalize(vec3(0.5, 0.7, 0.5));\n"
        "    vec3 albedo = vec3(0.7, 0.5, 0.3);\n"
        "    vec3 radiance = vec3(3.0);\n"
        "    vec3 col = albedo / PI * radiance * max(dot(n, l), 0.0);\n"
        "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);",
        "const float PI = 3.14159265;\n",
    )
    assert found(src) == []


def test_l007_tonemap_clamp_or_a_dim_single_light_are_fine() -> None:
    bright = (
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 lig = normalize(vec3(1.0));\n"
        "    vec3 col = 2.0 * vec3(0.8) * max(dot(n, lig), 0.0);\n"
    )
    out = "    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);"
    assert found(image(bright + "    col = col / (1.0 + col);\n" + out)) == []
    assert found(image(bright + "    col = 1.0 - exp(-col);\n" + out)) == []
    assert found(image(bright + "    col = clamp(col, 0.0, 1.0);\n" + out)) == []
    assert found(image(LIT + out)) == []


def test_l005_a_2d_vector_a_hash_argument_or_a_ray_plane_dot_is_not_lighting() -> None:
    # a "normal" must be a vec3 dotted with a light or view vector
    vignette = image("    vec2 N = fragCoord / iResolution.xy - 0.5;\n"
                     "    fragColor = vec4(vec3(1.0 - dot(N, N)), 1.0);")  # fmt: skip
    head = "float hash(vec2 n) { return fract(sin(dot(n, vec2(12.9898, 4.1414))) * 43758.5); }\n"
    hashed = image("    fragColor = vec4(vec3(hash(fragCoord)), 1.0);", head)
    plane = image(
        "    vec3 rd = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 n = vec3(0.0, 1.0, 0.0);\n"
        "    float t = -1.0 / dot(rd, n);\n"
        "    fragColor = vec4(vec3(fract(t)), 1.0);"
    )
    assert found(vignette) == found(hashed) == found(plane) == []


def test_l005_a_lighting_term_that_never_reaches_the_colour_does_not_count() -> None:
    dead = image(
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 lig = normalize(vec3(1.0));\n"
        "    float diff = dot(lig, n);\n"
        "    fragColor = vec4(0.5 + 0.5 * sin(n * 3.0), 1.0);"
    )
    assert found(dead, "L005") == []
    live = dead.replace("sin(n * 3.0)", "sin(n * 3.0) * diff")
    assert found(live, "L005") == [("L005", 5)]


def test_l005_a_light_named_vector_or_a_light_struct_counts() -> None:
    head = "struct Light { vec3 dir; vec3 color; };\n"
    src = image(
        "    vec3 nor = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    Light l = Light(normalize(vec3(1.0)), vec3(1.0));\n"
        "    vec3 ligt = normalize(vec3(1.0, 2.0, 0.5));\n"
        "    vec3 col = l.color * max(dot(nor, l.dir), 0.0) + 0.2 * max(dot(nor, ligt), 0.0);\n"
        "    fragColor = vec4(col, 1.0);",
        head,
    )
    assert found(src, "L005") == [("L005", 7)]


@pytest.mark.parametrize(
    "curve",
    ["col = pow(clamp(col, 0.0, 1.0), vec3(0.8));", "col = pow(col, vec3(GAMMA)) * 1.1;"],
)
def test_l005_an_output_curve_the_author_chose_counts(curve: str) -> None:
    src = image(LIT + f"    {curve}\n    fragColor = vec4(col, 1.0);", "#define GAMMA 1.3\n")
    assert found(src, "L005") == []


@pytest.mark.parametrize(
    "out",
    [
        "fragColor = vec4(col, length(fragCoord) * 0.01);",  # depth or a blur strength in alpha
        "fragColor = vec4(col, 1.0);\n    if (ivec2(fragCoord) == ivec2(0)) fragColor = vec4(1.0);",
        "fragColor = vec4(n * 0.5 + 0.5, 1.0);",  # a G-buffer normal
        "fragColor = vec4(col * 750.0 + 10.0 * vec3(0.5, 0.8, 1.0), 1.0);",  # HDR radiance
        "fragColor = vec4(mix(vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 0.0), step(0.5, col.x)), 1.0);",
    ],
)
def test_l005_l007_a_buffer_pass_or_a_palette_is_not_a_displayed_linear_image(out: str) -> None:
    assert found(image(LIT + f"    {out}"), "L005") == []
    bright = LIT.replace("vec3(0.8) *", "vec3(2.0) *")
    assert found(image(bright + "    fragColor = vec4(sqrt(col), 1.0);"), "L007") == [("L007", 5)]
    assert found(image(bright + f"    {out}"), "L007") == []


def test_l006_a_grade_or_a_mask_is_not_an_encoding() -> None:
    grade = image(
        LIT + "    vec3 uGamma = vec3(-0.25);\n"
        "    col = pow(max(vec3(0.0), col), max(vec3(0.0), 1.0 - uGamma));\n"
        "    fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);"
    )
    assert found(grade, "L006") == []
    mask = image(
        LIT + "    vec2 m = sqrt(abs(fract(fragCoord / 8.0) - 0.5));\n"
        "    float k = pow(m.x * m.y, 0.5);\n"
        "    fragColor = vec4(pow(col, vec3(1.0 / 2.2)) * k, 1.0);"
    )
    assert found(mask, "L006") == []


def test_l007_a_clamp_in_the_function_that_returns_the_colour_counts() -> None:
    head = (
        "vec3 render(vec2 fragCoord) {\n"
        "    vec3 n = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));\n"
        "    vec3 lig = normalize(vec3(1.0));\n"
        "    vec3 col = 2.0 * vec3(0.8) * max(dot(n, lig), 0.0);\n"
        "    CLIP\n"
        "    return col;\n"
        "}\n"
    )
    out = "    fragColor = vec4(pow(render(fragCoord), vec3(0.4545)), 1.0);"
    assert found(image(out, head.replace("CLIP", "")), "L007") == [("L007", 9)]
    assert found(image(out, head.replace("CLIP", "col = clamp(col, 0., 1.);")), "L007") == []


# --- L008 -----------------------------------------------------------------------------------

SPLIT = """#define PI 3.14159265
vec3 fresnelSchlick(vec3 f0, float VoH) { return f0 + (1.0 - f0) * pow(1.0 - VoH, 5.0); }
vec3 shade(vec3 albedo, vec3 f0, float metallic, float VoH, float NoL, float D, float Vis) {
    vec3 F = fresnelSchlick(f0, VoH);
    return DIFFUSE + F * D * Vis * NoL;
}
"""


def test_l008_diffuse_not_scaled_by_one_minus_f() -> None:
    assert found(SPLIT.replace("DIFFUSE", "albedo / PI * NoL")) == [("L008", 5)]


@pytest.mark.parametrize(
    "diffuse",
    [
        "(1.0 - F) * albedo / PI * NoL",
        "(vec3(1.0) - F) * (1.0 - metallic) * albedo / PI * NoL",
        "albedo * (1.0 - metallic) / PI * NoL",
    ],
)
def test_l008_split_diffuse_is_fine(diffuse: str) -> None:
    assert found(SPLIT.replace("DIFFUSE", diffuse)) == []


def test_l008_constant_colour_times_n_dot_l_is_a_diffuse_term() -> None:
    assert found(SPLIT.replace("DIFFUSE", "vec3(0.5) / PI * NoL")) == [("L008", 5)]


def test_l008_split_through_a_local_kd() -> None:
    src = SPLIT.replace(
        "    return DIFFUSE", "    vec3 kD = (1.0 - F) * (1.0 - metallic);\n    return kD * albedo"
    )
    assert found(src) == []


# --- the corpora, the fixture template, the catalog -------------------------------------------


@pytest.mark.parametrize(
    "path",
    sorted((CORPORA / "valid").glob("*.glsl")) + sorted((CORPORA / "lint").glob("*.glsl")),
    ids=lambda p: f"{p.parent.name}/{p.stem}",
)
def test_valid_corpus_has_no_lighting_findings(path: Path) -> None:
    findings = [(f.code, f.line) for f in lint_source(path.read_text(), str(path), FAST)]
    if path.name == "04_structs.glsl":
        # Lambert-lit and written out linear: the corpus file is about structs, and it does
        # lack the display encoding L005 is for.
        assert findings == [("L005", 33)]
    else:
        assert findings == []


def test_template_reference_lints_clean_of_lighting_rules() -> None:
    assert lint_source(template_source(), "template.glsl", FAST) == []
