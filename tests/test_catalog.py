"""The catalog: front matter agrees with the parsed bodies, every snippet compiles with its
dependencies, and a broken snippet is caught with a message that names it."""

from __future__ import annotations

import pytest

from glint.compiler.catalog import Catalog, load_catalog, parse_snippet, snippets_root
from glint.compiler.catalog_check import check_front_matter, compile_alone, snippet_symbols
from glint.compiler.catalog_info import catalog_entries
from glint.compiler.errors import InputError
from glint.compiler.slots import SLOTS

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
    body = GGX_BODY.replace("float NoH, float a", "float NoH, float roughness").replace(
        "a * a", "roughness * roughness"
    ).replace("(a2 - 1.0)", "(a2 - 1.0)")
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
        (front("[]", "[]", 'params = { K = { default = 1 } }\n'), "param 'K' needs a type"),
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
        "Surface makeSurface(vec3 P, vec3 N, vec3 V, vec3 albedo, float roughness, float metallic)",
        "Dots lightDots(Surface s, vec3 L)",
    ]
