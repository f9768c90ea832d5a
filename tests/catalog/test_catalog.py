"""The catalog: front matter agrees with the parsed bodies, every snippet compiles with its
dependencies, and a broken snippet is caught with a message that names it."""

from __future__ import annotations

import pytest

from glint.compiler.catalog.info import catalog_entries
from glint.compiler.catalog.loader import Catalog, load_catalog, parse_snippet, snippets_root
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.errors import InputError
from glint.compiler.verify.catalog_check import check_front_matter, compile_alone, snippet_symbols

CATALOG = load_catalog()
IDS = sorted(CATALOG.snippets)


@pytest.mark.parametrize("snippet_id", IDS)
def test_front_matter_matches_the_body(snippet_id: str) -> None:
    snippet = CATALOG.snippets[snippet_id]
    assert [str(p) for p in check_front_matter(snippet, CATALOG)] == []


@pytest.mark.parametrize("snippet_id", IDS)
def test_snippet_compiles_with_its_dependencies(snippet_id: str) -> None:
    errors = [d for d in compile_alone(CATALOG.snippets[snippet_id], CATALOG)]
    assert [str(d) for d in errors] == []


def test_every_slot_with_an_entry_has_a_variant() -> None:
    for slot in SLOTS.values():
        assert CATALOG.in_slot(slot.name), f"slot {slot.name} has no snippet"


def test_every_error_budget_says_why() -> None:
    # The docs site shows budget_why under the measured table: a reader must see why the budget
    # is what it is (design error of the model, or what was measured and the headroom left).
    budgeted = [s for s in CATALOG.snippets.values() if s.error_budget]
    assert budgeted
    for snippet in budgeted:
        assert snippet.budget_why.strip(), f"{snippet.id}: error_budget without budget_why"
    for snippet in CATALOG.snippets.values():
        assert len(snippet.budget_why) <= 300, f"{snippet.id}: budget_why is too long"


def with_snippet(text: str, relpath: str = "snippets/D/test.glsl") -> tuple[Catalog, object]:
    snippet = parse_snippet(text, relpath)
    catalog = Catalog(dict(CATALOG.snippets) | {snippet.id: snippet})
    return catalog, snippet


def front(provides: str, requires: str, extra: str = "") -> str:
    return (
        "/* ---\n"
        'id = "D.test"\nslot = "D"\nsummary = "test"\n'
        f"provides = {provides}\nrequires = {requires}\nsources = []\n{extra}"
        "--- */\n"
    )


GGX_BODY = """float distribution(float NoH, float a) {
    float a2 = a * a;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}
"""


def messages(text: str) -> list[str]:
    catalog, snippet = with_snippet(text)
    return [p.message for p in check_front_matter(snippet, catalog)]  # type: ignore[arg-type]


def test_a_correct_snippet_has_no_problem() -> None:
    assert messages(front('["distribution"]', '["PI"]') + GGX_BODY) == []


def test_undeclared_requirement() -> None:
    assert messages(front('["distribution"]', "[]") + GGX_BODY) == [
        "uses 'PI', which is not declared in requires"
    ]


def test_unused_requirement() -> None:
    assert messages(front('["distribution"]', '["PI", "Dots"]') + GGX_BODY) == [
        "requires 'Dots', but the body never uses it"
    ]


def test_undeclared_and_missing_provides() -> None:
    body = GGX_BODY + "float helper(float x) { return x; }\n"
    assert messages(front('["distribution", "D_GGX"]', '["PI"]') + body) == [
        "provides 'D_GGX', but the body does not define it",
        "defines 'helper', which is not declared in provides",
    ]


def test_undeclared_call_is_caught() -> None:
    body = GGX_BODY.replace("return a2", "return square(a) * a2")
    assert "uses 'square', which is not declared in requires" in messages(
        front('["distribution"]', '["PI"]') + body
    )


def test_entry_must_have_the_slot_prototype() -> None:
    body = (
        GGX_BODY.replace("float NoH, float a", "float NoH, float roughness")
        .replace("a * a", "roughness * roughness")
        .replace("(a2 - 1.0)", "(a2 - 1.0)")
    )
    problems = messages(front('["distribution"]', '["PI"]') + body)
    assert problems == [
        "entry `float distribution(float NoH, float roughness)` must have the slot's "
        "prototype `float distribution(float NoH, float a)`"
    ]


def test_slot_requirement_counts_its_entry_as_used() -> None:
    body = "float distribution(float NoH, float a) { return fresnel(vec3(0.04), NoH).x; }\n"
    assert messages(front('["distribution"]', '["F"]') + body) == []


def test_unused_parameter() -> None:
    extra = 'params = { GAIN = { type = "float", default = 1.0 } }\n'
    assert messages(front('["distribution"]', '["PI"]', extra) + GGX_BODY) == [
        "declares parameter 'GAIN', but the body never uses it"
    ]


def test_a_snippet_that_does_not_compile_is_reported_at_its_line() -> None:
    body = GGX_BODY.replace("float a2 = a * a;", "float a2 = a * b;")
    catalog, snippet = with_snippet(front('["distribution"]', '["PI"]') + body)
    diagnostics = compile_alone(snippet, catalog)  # type: ignore[arg-type]
    assert any(d.file == "snippets/D/test.glsl" and d.line == 10 for d in diagnostics), [
        str(d) for d in diagnostics
    ]


def test_symbols_keep_the_file_lines() -> None:
    ggx = CATALOG.snippets["D.ggx"]
    function = snippet_symbols(ggx).functions[0]
    text = (snippets_root() / "D" / "ggx.glsl").read_text().splitlines()
    assert "float distribution" in text[function.line - 1]
    assert function.line > ggx.body_line


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("float x;\n", "must open with '/* ---' front matter"),
        ("/* ---\nid = 'D.test'\n", "front matter is not closed"),
        ("/* ---\nid = = 1\n--- */\n", "front matter is not valid TOML"),
        ("/* ---\nid = 'D.test'\n--- */\n", "front matter lacks"),
        (front("[]", "[]", "colour = 1\n"), "unknown front-matter key ['colour']"),
        (front("[]", "[]").replace('id = "D.test"', 'id = "D.other"'), "the folder is the slot"),
        (front("[]", "[]", "params = { K = { default = 1 } }\n"), "param 'K' needs a type"),
    ],
)
def test_bad_front_matter(text: str, expected: str) -> None:
    with pytest.raises(InputError) as info:
        parse_snippet(text, "snippets/D/test.glsl")
    assert expected in info.value.message
    assert info.value.message.startswith("snippets/D/test.glsl")


def test_catalog_entries_carry_the_parsed_signatures() -> None:
    entries = {e["id"]: e for e in catalog_entries()}
    assert entries["V.smith_ggx_correlated"]["signature"] == ["float visibility(Dots d, float a)"]
    assert entries["camera.orbit"]["signature"] == [
        "void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd)"
    ]
    assert entries["core.surface"]["signature"] == [
        "Surface makeSurface(vec3 P, vec3 N, vec3 V, vec3 albedo, float roughness)",
        "Dots lightDots(Surface s, vec3 L)",
    ]


# Presets: a variant that is another with new parameter defaults and no body of its own.

BASE = """/* ---
id = "shadow.base"
slot = "shadow"
summary = "a base"
provides = ["shadow"]
requires = ["map"]
params.STEPS = { type = "int", default = 24, range = [1, 256] }
params.K = { type = "float", default = 8.0 }
sources = ["somewhere"]
--- */
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float t = tmin;
    for (int i = 0; i < STEPS; i++) t += K * map(ro + rd * t);
    return t > tmax ? 1.0 : 0.0;
}
"""


def preset(params: str = "{ STEPS = 12 }", of: str = "shadow.base", extra: str = "") -> str:
    return (
        f'/* ---\nid = "shadow.quick"\nslot = "shadow"\nsummary = "fewer steps"\n'
        f'preset_of = "{of}"\nparams = {params}\n{extra}--- */\n'
    )


def load_presets(tmp_path, preset_text: str):  # type: ignore[no-untyped-def]
    (tmp_path / "shadow").mkdir()
    (tmp_path / "shadow" / "base.glsl").write_text(BASE)
    (tmp_path / "shadow" / "quick.glsl").write_text(preset_text)
    return load_catalog(tmp_path)


def test_a_preset_runs_its_base_with_new_defaults(tmp_path) -> None:  # type: ignore[no-untyped-def]
    catalog = load_presets(tmp_path, preset(extra='sources = ["a note on step counts"]\n'))
    base, quick = catalog.get("shadow.base"), catalog.get("shadow.quick")
    assert quick.preset_of == "shadow.base" and base.preset_of == ""
    assert quick.body == base.body and quick.provides == base.provides
    assert quick.requires == base.requires
    assert quick.sources == ("somewhere", "a note on step counts")
    assert quick.params["STEPS"].default == 12 and base.params["STEPS"].default == 24
    assert quick.params["K"] == base.params["K"]
    # The code is the base's, so errors point there; the snippet itself is the preset's file.
    assert quick.relpath == "snippets/shadow/base.glsl" and quick.body_line == base.body_line
    assert quick.file == "snippets/shadow/quick.glsl"
    assert list(catalog.snippets) == ["shadow.base", "shadow.quick"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (preset("{ STEPZ = 12 }"), "param 'STEPZ' is not a parameter of shadow.base (it has: "),
        (preset("{ STEPS = 1000 }"), "param 'STEPS' = 1000 is not a int in [1, 256]"),
        (preset("{ STEPS = 1.5 }"), "param 'STEPS' = 1.5 is not a int"),
        (preset("{ K = true }"), "param 'K' = True is not a float"),
        (preset("{ }"), "must set at least one of its base's"),
        (preset(of="shadow.nope"), "preset_of 'shadow.nope' is not a variant with a body"),
        (preset(extra='provides = ["shadow"]\n'), "unknown front-matter key ['provides']"),
        (preset() + "float x;\n", "a preset has no GLSL body"),
        (preset().replace("params = { STEPS = 12 }\n", ""), "a preset's front matter lacks params"),
    ],
)
def test_bad_preset(tmp_path, text: str, expected: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InputError) as info:
        load_presets(tmp_path, text)
    assert info.value.message.startswith("snippets/shadow/quick.glsl: ")
    assert expected in info.value.message


def test_a_preset_of_a_preset_is_refused(tmp_path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "shadow").mkdir()
    (tmp_path / "shadow" / "base.glsl").write_text(BASE)
    (tmp_path / "shadow" / "quick.glsl").write_text(preset())
    second = preset(of="shadow.quick").replace("shadow.quick", "shadow.quicker", 1)
    (tmp_path / "shadow" / "quicker.glsl").write_text(second)
    with pytest.raises(InputError, match="is itself a preset; name its base"):
        load_catalog(tmp_path)


def test_catalog_presets_are_listed_checked_and_composed() -> None:
    from glint import compose
    from glint.compiler.compose.linking.standalone import standalone_source
    from glint.compiler.target.glslang import validate

    soft_12 = CATALOG.get("shadow.soft_12")
    assert soft_12.preset_of == "shadow.soft" and soft_12.params["SHADOW_STEPS"].default == 12
    entry = next(e for e in catalog_entries() if e["id"] == "shadow.soft_12")
    assert entry["file"] == "snippets/shadow/soft_12.glsl" and entry["preset_of"] == "shadow.soft"
    assert entry["signature"] == ["float shadow(vec3 ro, vec3 rd, float tmin, float tmax)"]
    assert {p["name"]: p["default"] for p in entry["params"]}["SHADOW_STEPS"] == 12
    assert "#define SHADOW_STEPS 12\n" in standalone_source(soft_12, CATALOG)
    shader = compose(variants={"shadow": "soft_12"}).text
    assert "#define SHADOW_STEPS 12\n" in shader and "shadow.soft_12" in shader
    assert "// source: snippets/shadow/soft.glsl:" in shader
    assert validate(shader, "soft_12.glsl") == []
