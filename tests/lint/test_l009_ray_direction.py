"""L009 ray-direction-as-view: a ray direction (marched along, pointing away from the eye) in
the place of the view vector, found where the evidence is, and the correct forms left alone."""

from __future__ import annotations

from glint.lint.options import Options
from glint.lint.runner import lint_source

ONLY = Options(select=["L009"], glslang=False)

SCENE = """
float map(vec3 p) { return length(p) - 1.0; }
vec3 nrm(vec3 p) { vec2 e = vec2(1e-3, 0.0);
    return normalize(vec3(map(p + e.xyy) - map(p - e.xyy), map(p + e.yxy) - map(p - e.yxy),
                          map(p + e.yyx) - map(p - e.yyx))); }
float march(vec3 ro, vec3 rd) { float t = 0.0;
    for (int i = 0; i < 64; i++) { float h = map(ro + rd * t); if (h < 1e-3) break; t += h; }
    return t; }
float spec(vec3 n, vec3 v, vec3 l) { vec3 h = normalize(v + l);
    return pow(max(dot(n, h), 0.0), 32.0) * max(dot(n, v), 0.0); }
"""


def lines(body: str) -> list[int]:
    text = SCENE + "void mainImage(out vec4 c, in vec2 f) {\n" + body + "\n}\n"
    first = text.count("\n", 0, text.index("void mainImage")) + 2
    return [x.line - first + 1 for x in lint_source(text, "x.glsl", ONLY) if x.code == "L009"]


def test_ray_direction_passed_as_the_view_vector_is_found_at_the_call() -> None:
    body = """vec3 rd = normalize(vec3(f / 400.0 - 1.0, 1.5)), ro = vec3(0.0, 0.0, -3.0);
    float t = march(ro, rd); vec3 n = nrm(ro + rd * t), l = normalize(vec3(1.0));
    c = vec4(vec3(spec(n, rd, l)), 1.0);"""
    assert lines(body) == [3]


def test_the_negated_ray_is_the_view_vector_and_is_left_alone() -> None:
    body = """vec3 rd = normalize(vec3(f / 400.0 - 1.0, 1.5)), ro = vec3(0.0, 0.0, -3.0);
    float t = march(ro, rd); vec3 n = nrm(ro + rd * t), l = normalize(vec3(1.0));
    c = vec4(vec3(spec(n, -rd, l)), 1.0);"""
    assert lines(body) == []


def test_direct_uses_in_the_marching_function() -> None:
    body = """vec3 rd = normalize(vec3(f / 400.0 - 1.0, 1.5)), ro = vec3(0.0, 0.0, -3.0);
    vec3 p = ro; for (int i = 0; i < 64; i++) { p += rd * map(p); }
    vec3 nor = nrm(p), lig = normalize(vec3(1.0));
    vec3 h = normalize(rd + lig);
    float fre = pow(clamp(1.0 + dot(nor, rd), 0.0, 1.0), 5.0);
    float bad = 1.0 - dot(nor, rd);
    float ok = pow(max(dot(nor, normalize(lig - rd)), 0.0), 16.0);
    c = vec4(vec3(dot(nor, h) + fre + bad + ok), 1.0);"""
    assert lines(body) == [4, 6]


def test_shadow_rays_march_along_the_light_and_are_not_ray_directions() -> None:
    body = """vec3 p = vec3(f, 0.0), lig = normalize(vec3(1.0)), nor = nrm(p);
    float s = 1.0; for (float t = 0.01; t < 4.0; t += 0.1) s = min(s, map(p + lig * t));
    c = vec4(vec3(max(dot(nor, lig), 0.0) * s), 1.0);"""
    assert lines(body) == []
