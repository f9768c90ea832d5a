"""Symbols: what a module defines, calls and needs from elsewhere."""

from __future__ import annotations

from glint.compiler.glsl.symbols import Param, analyze, reachable
from glint.compiler.target.shadertoy import UNIFORM_NAMES

SNIPPET = """
float distribution(float NoH, float a) {
    float a2 = a * a;
    float f = (NoH * a2 - NoH) * NoH + 1.0;
    return a2 / (PI * f * f);
}
"""


def test_macro_from_another_snippet_is_free() -> None:
    mod = analyze(SNIPPET, "D/ggx.glsl")
    (fn,) = mod.functions
    assert fn.name == "distribution"
    assert fn.prototype == "float distribution(float NoH, float a)"
    assert fn.params == [Param("", "float", "NoH"), Param("", "float", "a")]
    assert fn.line == 2 and fn.end_line == 6
    assert fn.uses == {"PI"}
    assert fn.calls == set()
    assert mod.free == {"PI"}
    assert mod.defined == {"distribution"}


def test_predefined_macro_is_expanded_away() -> None:
    assert analyze(SNIPPET, predefined={"PI": "3.14159"}).free == set()


def test_main_image_prototype_keeps_qualifiers() -> None:
    mod = analyze(
        "void mainImage( out vec4 fragColor,\n in vec2 fragCoord ) { fragColor = vec4(0); }"
    )
    assert mod.functions[0].prototype == "void mainImage(out vec4 fragColor, in vec2 fragCoord)"


def test_calls_builtins_constructors_and_structs() -> None:
    src = """
    struct Hit { float t; vec3 n; };
    Hit trace(vec3 ro, vec3 rd) {
        Hit h = Hit(march(ro, rd), normalize(vec3(1.0)));
        return h;
    }
    """
    mod = analyze(src)
    fn = mod.functions[0]
    assert fn.calls == {"march"}
    assert fn.uses == {"Hit"}
    assert mod.structs == ["Hit"]
    assert mod.free == {"march"}


def test_locals_params_scopes_and_fields_are_not_free() -> None:
    src = """
    float g(vec3 p, float arr[2]) {
        float s = 0.0;
        for (int i = 0; i < 2; i++) { float w = arr[i]; s += w * p.x; }
        { float inner = 1.0; s += inner; }
        s += inner2;
        return s + float(arr.length()) + iTime + gl_FragCoord.x;
    }
    """
    fn = analyze(src, provided={"iTime"}).functions[0]
    assert fn.uses == {"inner2"}
    # the front end knows no target: ShaderToy's uniforms are free unless the target says so
    assert analyze(src).functions[0].uses == {"inner2", "iTime"}
    assert fn.params[1] == Param("", "float[2]", "arr")
    assert fn.prototype == "float g(vec3 p, float arr[2])"


def test_block_scope_ends() -> None:
    fn = analyze("float h() { { float k = 1.0; } return k; }").functions[0]
    assert fn.uses == {"k"}


def test_own_macros_globals_and_their_dependencies() -> None:
    src = """
    #define SUN_DIR normalize(vec3(1.0, 0.5, 0.2))
    #define X foo(1.0)
    #define SQ(x) ((x) * (x))
    const float EPS = 1e-3 * SCALE;
    vec2 gA, gB = vec2(EPS);
    float shade(vec3 n) { return SQ(dot(n, SUN_DIR)) + EPS; }
    void mainImage(out vec4 c, in vec2 p) { c = vec4(shade(vec3(0, 1, 0))); }
    void unused() { float y = X; }
    """
    mod = analyze(src, "m.glsl")
    assert mod.macros == ["SUN_DIR", "X", "SQ"]
    assert mod.globals == ["EPS", "gA", "gB"]
    assert mod.free == {"SCALE", "foo"}
    assert mod.calls == {"shade", "foo"}  # `unused` calls foo through X
    shade = mod.functions[0]
    assert shade.uses == {"SQ", "SUN_DIR", "EPS"}
    assert reachable(mod, {"mainImage"}) == {"mainImage", "shade", "SQ", "SUN_DIR", "EPS", "SCALE"}
    assert "foo" in reachable(mod, {"unused"})


def test_prototype_only_is_not_a_definition() -> None:
    mod = analyze("float noise(vec2 p);\nfloat fbm(vec2 p) { return noise(p) * 0.5; }")
    assert mod.defined == {"fbm"}
    assert mod.free == {"noise"}


def test_function_like_macro_from_elsewhere_is_a_call() -> None:
    mod = analyze("float f(float x) { return SATURATE(x); }")
    assert mod.functions[0].calls == {"SATURATE"}
    assert mod.free == {"SATURATE"}


def test_struct_dependencies_and_local_structs() -> None:
    src = """
    struct A { float x; };
    struct B { A a; Other o; } gb;
    float f() { struct L { float q; }; L l = L(1.0); return l.q; }
    """
    mod = analyze(src)
    assert mod.structs == ["A", "B"]
    assert mod.globals == ["gb"]
    assert mod.free == {"Other"}
    assert reachable(mod, {"gb"}) == {"gb", "B", "A", "Other"}
    assert mod.functions[0].uses == set()


def test_whole_corpus_shader() -> None:
    from pathlib import Path

    path = Path(__file__).resolve().parent.parent / "corpus" / "valid" / "16_pbr.glsl"
    mod = analyze(path.read_text(encoding="utf-8"), path.name, provided=UNIFORM_NAMES)
    assert mod.free == set()  # ShaderToy's uniforms come from the target
    assert {"D_GGX", "V_SmithGGXCorrelated", "F_Schlick", "brdf", "mainImage"} <= mod.defined
    assert reachable(mod, {"mainImage"}) >= {"brdf", "D_GGX", "PI", "MIN_ROUGHNESS"}


def test_struct_from_another_snippet_is_a_type() -> None:
    src = "vec3 diffuse(Material m, in Dots d) { Material k = m; return k.albedo * d.NoL; }"
    mod = analyze(src)
    fn = mod.functions[0]
    assert fn.prototype == "vec3 diffuse(Material m, in Dots d)"
    assert mod.free == {"Material", "Dots"}
