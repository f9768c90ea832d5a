"""A fuzzer over scenes: tables built from the scene schema's own keys (every model's fields,
found by introspection), filled with values of the right type, then some of them replaced:
extreme numbers (inf, nan, 1e300, -0.0, 1e-300, integers past 64 bits), booleans, unicode and
hostile strings, deep groups and lists, arrays of the wrong length, keys removed. Composing
one in-process either gives a shader (a string) or raises a GlintError; anything else (a
KeyError, a ZeroDivisionError, a RecursionError, a hang) is a bug.

A second, smaller run keeps to values of the right type, so that most scenes compose, and
holds what they compose to glslangValidator; a third edits the example scene files at random
(TOML syntax included)."""

from __future__ import annotations

import math
import types
import typing
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from pydantic import BaseModel

import glint
from glint.compiler.errors import GlintError
from glint.compiler.scene.model import Scene, default_scene_path, parse_scene
from glint.compiler.scene.shapes import Mesh

MATERIALS = ["m", "n"]  # the names objects use, so that many scenes get past the references
HOSTILE = [
    "",
    "*/",
    "/*",
    "a\nb",
    "x */ vec3 injected; /*",
    "\n#error injected\n",
    "\\",
    "\u2028\u202e",
    "\x00",
    "é🙂",
    "../up",
    "m",
]
EXTREME = [
    0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e-300, 1e-40, 1e-30, 1e30, 3.4e38, 3.5e38, 1e300,
    -1e300, math.inf, -math.inf, math.nan, 2**63, -(2**63) - 1, 2**200, 16777217,
]  # fmt: skip


def _numbers() -> st.SearchStrategy[Any]:
    return st.one_of(
        st.sampled_from(EXTREME),
        st.floats(allow_nan=True, allow_infinity=True),
        st.floats(min_value=-10.0, max_value=10.0),
        st.integers(min_value=-(2**80), max_value=2**80),
        st.integers(min_value=-3, max_value=10),
    )


def _strings() -> st.SearchStrategy[str]:
    return st.one_of(st.sampled_from(HOSTILE), st.text(max_size=12))


def _junk(depth: int = 2) -> st.SearchStrategy[Any]:
    """Any TOML-like value: what a key of another type gets."""
    leaves = st.one_of(_numbers(), _strings(), st.booleans())
    return st.recursive(
        leaves,
        lambda inner: st.one_of(
            st.lists(inner, max_size=4), st.dictionaries(_strings(), inner, max_size=3)
        ),
        max_leaves=6,
    )


_MODEL_STRATEGIES: dict[type, st.SearchStrategy[Any]] = {}


def _for(annotation: Any, key: str = "") -> st.SearchStrategy[Any]:
    """Values of this annotation's type, mostly plausible, now and then extreme (the
    mutations in _mutated bring the values of other types)."""
    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Annotated:
        return _for(args[0], key)
    if origin in (typing.Union, types.UnionType):
        members = [a for a in args if a is not type(None)]
        return st.one_of(*(_for(a, key) for a in members))
    if origin is typing.Literal:
        return st.sampled_from(args)
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return _model(annotation)
    if annotation is bool:
        return st.booleans()
    if annotation is int:
        return st.integers(min_value=0, max_value=3)
    if annotation is float:
        return st.one_of(
            st.floats(min_value=0.05, max_value=3.0),
            st.sampled_from([0.0, 0.5, 1.0, 2.0, -1.0]),
        )
    if annotation is str:
        if key == "material":
            return st.sampled_from(MATERIALS)
        if key == "file":
            return st.sampled_from(["nope.glsl", "nope.obj", "/dev/zero", "/dev/null", ""])
        return _strings()
    if origin is list:
        if key == "children":
            return st.lists(st.deferred(_shapes), min_size=1, max_size=2)
        return st.lists(_for(args[0], key), min_size=3, max_size=3)
    if origin is dict:
        keys = st.sampled_from(MATERIALS) if key == "materials" else _strings()
        return st.dictionaries(keys, _for(args[1], key), min_size=1, max_size=2)
    return _junk()


def _model(model: type[BaseModel]) -> st.SearchStrategy[dict[str, Any]]:
    """A table of this model: its tag and required keys, some of the others."""
    cached = _MODEL_STRATEGIES.get(model)
    if cached is not None:
        return cached
    fields = model.model_fields
    tags = {
        k: st.just(typing.get_args(f.annotation)[0])
        for k, f in fields.items()
        if typing.get_origin(f.annotation) is typing.Literal and k in ("shape", "type")
    }
    required = {k: _for(f.annotation, k) for k, f in fields.items()
                if f.is_required() and k not in tags}  # fmt: skip
    optional = {k: _for(f.annotation, k) for k, f in fields.items()
                if not f.is_required() and k not in tags}  # fmt: skip
    built = st.fixed_dictionaries({**tags, **required}, optional=optional)
    # behind deferred: a strategy's repr holds those it is made of, and the models nest
    # (groups in groups), which makes hypothesis' repr of a failing case megabytes long
    strategy = st.deferred(lambda: built)
    _MODEL_STRATEGIES[model] = strategy
    return strategy


def _shapes() -> st.SearchStrategy[dict[str, Any]]:
    shape = typing.get_args(Scene.model_fields["objects"].annotation)[0]
    return _for(shape, "objects")


def _scenes() -> st.SearchStrategy[dict[str, Any]]:
    """A scene table whose objects name the materials it defines."""
    objects = st.lists(
        _shapes().map(lambda o: {**o, "material": o.get("material", "m")}),
        min_size=1,
        max_size=3,
    )
    material = _model(Scene.model_fields["materials"].annotation.__args__[1])
    return st.builds(
        lambda scene, objects, materials: {**scene, "objects": objects, "materials": materials},
        _model(Scene),
        objects,
        st.fixed_dictionaries({"m": material}, optional={"n": material}),
    )


def _places(value: Any) -> list[tuple[Any, ...]]:
    """The path of every key and item under `value`, to 40 levels (a deep group or list put
    there by an earlier mutation is not walked to its bottom)."""
    found: list[tuple[Any, ...]] = []
    stack: list[tuple[Any, tuple[Any, ...]]] = [(value, ())]
    while stack:
        value, path = stack.pop()
        if len(path) >= 40:
            continue
        items = value.items() if isinstance(value, dict) else (
            enumerate(value) if isinstance(value, list) else ()
        )  # fmt: skip
        for key, child in items:
            found.append((*path, key))
            stack.append((child, (*path, key)))
    return found


def _deep_group(depth: int) -> dict[str, Any]:
    part: dict[str, Any] = {"shape": "sphere"}
    for _ in range(depth):
        part = {"shape": "union", "children": [part], "position": [0.1, 0.0, 0.0]}
    return part


def _deep_list(depth: int) -> list[Any]:
    value: list[Any] = [1.0]
    for _ in range(depth):
        value = [value]
    return value


_MUTATIONS = st.one_of(
    _junk(),
    st.integers(min_value=200, max_value=2000).map(_deep_list),
    st.sampled_from(EXTREME),
    st.sampled_from(HOSTILE),
    st.lists(_numbers(), max_size=5),
    st.integers(min_value=95, max_value=105).map(_deep_group),
    st.just(_MISSING := object()),
)


@st.composite
def _mutated(draw: st.DrawFn) -> dict[str, Any]:
    """A scene with up to three of its values replaced by one of another type, an extreme
    number, a hostile string, a deep group, or removed."""
    data = draw(_scenes())
    for _ in range(draw(st.integers(min_value=0, max_value=3))):
        places = _places(data)
        path = draw(st.sampled_from(places))
        parent = data
        for key in path[:-1]:
            parent = parent[key]
        value = draw(_MUTATIONS)
        if value is _MISSING:
            del parent[path[-1]]
        else:
            parent[path[-1]] = value
    if draw(st.booleans()) and isinstance(data.get("camera"), dict):
        data["camera"] = draw(st.sampled_from(CAMERAS))
    return data


# Cameras straight above, below and beside the target, and degenerate ones.
CAMERAS = [
    {"type": "lookat", "position": [0.0, 4.0, 0.0]},
    {"type": "lookat", "position": [0.0, -4.0, 0.0]},
    {"type": "lookat", "position": [0.0, 0.0, 1e-20]},
    {"type": "lookat", "position": [1e8, 0.0, 0.0], "target": [1e8 + 1.0, 0.0, 0.0]},
    {"type": "orbit", "radius": 1e-20, "height": 3.0},
    {"type": "orbit", "radius": 1e-30, "height": 0.0},
]


def _compose(data: dict[str, Any]) -> str | None:
    """The shader of the scene (a mesh scene's first fragment stage), or None when glint
    refused it with a GlintError."""
    try:
        objects = data.get("objects")
        meshes = isinstance(objects, list) and any(
            isinstance(o, dict) and o.get("shape") == "mesh" for o in objects
        )
        if meshes:
            composed = glint.compose_mesh(data, target="mesh-webgl2")
            assert isinstance(composed.explain(), str)
            files = composed.files("out/shader")  # a material's name is in a file's
            assert all(path.parent.name == "out" for path in files)
            return "\n".join(files.values())
        shader = glint.compose(data)
        assert isinstance(shader.explain(), str)
        return shader.text
    except GlintError as error:
        event(f"refused: {error.message.split(':')[1].strip()[:30]}")
        assert isinstance(error.message, str) and error.message
        assert "Traceback" not in error.message
        return None


FUZZ = settings(
    max_examples=150,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                           HealthCheck.filter_too_much],
)  # fmt: skip


@FUZZ
@given(_mutated())
def test_any_scene_composes_or_is_refused_with_a_glint_error(data: dict[str, Any]) -> None:
    text = _compose(data)
    event("composed" if text is not None else "refused")
    assert text is None or isinstance(text, str)


@settings(FUZZ, max_examples=40)
@given(_scenes())
def test_a_scene_of_well_typed_values_composes_to_a_shader_glslang_accepts(
    data: dict[str, Any],
) -> None:
    from glint.compiler.target.glslang import validate

    data["objects"] = [o for o in data["objects"] if o.get("shape") != "mesh"] or [
        {"shape": "sphere", "material": "m"}
    ]
    data.pop("geometry", None)  # its file does not exist: a GLSL file is not fuzzed here
    text = _compose(data)
    event("composed" if text is not None else "refused")
    if text is not None:
        assert [str(d) for d in validate(text, "<fuzzed>", "shadertoy")] == []


EXAMPLES = sorted(default_scene_path().parent.glob("*.toml"))


@FUZZ
@given(
    st.sampled_from(EXAMPLES),
    st.lists(
        st.tuples(st.integers(min_value=0), st.integers(min_value=0, max_value=8), _strings()),
        min_size=1,
        max_size=4,
    ),
)
def test_an_example_scene_file_edited_at_random_composes_or_is_refused(
    example: Path, edits: list[tuple[int, int, str]]
) -> None:
    """Bytes cut from and strings pasted into a real scene file (TOML syntax broken, keys and
    values garbled); the file keeps its folder, so a [geometry] file is still found."""
    text = example.read_text(encoding="utf-8")
    for at, cut, pasted in edits:
        at %= len(text) + 1
        text = text[:at] + pasted + text[at + cut :]
    try:
        scene = parse_scene(text, str(example))
    except GlintError:
        return
    try:
        if scene.is_mesh:
            glint.compose_mesh(scene, target="mesh-webgl2")
        else:
            assert isinstance(glint.compose(scene).text, str)
    except GlintError:
        pass


def _schema_models(model: type[BaseModel] = Scene, found: set[type] | None = None) -> set[type]:
    """Every model (table) reachable from the scene's fields."""
    found = set() if found is None else found
    if model in found:
        return found
    found.add(model)
    stack = [f.annotation for f in model.model_fields.values()]
    while stack:
        annotation = stack.pop()
        if isinstance(annotation, type) and issubclass(annotation, BaseModel):
            _schema_models(annotation, found)
        stack.extend(typing.get_args(annotation))
    return found


def test_the_fuzzer_generates_every_table_of_the_schema() -> None:
    """A model added to the schema is fuzzed without editing this file."""
    _scenes(), _shapes()  # noqa: B018 - builds the strategy of every model
    schema = _schema_models()
    assert Mesh in schema and len(schema) > 20
    assert schema <= set(_MODEL_STRATEGIES)
