"""A ShaderToy project read from its JSON (the export's and the API's forms) or from a folder of
tabs: the passes in ShaderToy's order, what each channel reads, and one clear message for what
glint cannot draw."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest

from glint.compiler.errors import InputError
from glint.compiler.target.shadertoy_project import read_project

PROJECT = Path(__file__).resolve().parents[1] / "corpus" / "projects" / "feedback"


def _summary(folder_or_json: Path) -> list[tuple[str, list[tuple[int, str, str]]]]:
    project = read_project(folder_or_json)

    def source(entry: Any) -> str:
        return str(entry.buffer or (entry.file.name if entry.file else ""))

    return [
        (item.name, [(i.channel, i.kind, source(i)) for i in item.inputs])
        for item in project.passes
    ]


def test_the_folder_and_the_json_export_are_the_same_project() -> None:
    expected = [
        ("Buffer A", [(0, "buffer", "A")]),
        ("Image", [(0, "buffer", "A"), (1, "texture", "checker.png")]),
    ]
    assert _summary(PROJECT) == expected
    assert _summary(PROJECT / "shader.json") == expected
    folder, exported = read_project(PROJECT), read_project(PROJECT / "shader.json")
    assert folder.common == exported.common and "vec3 tint()" in folder.common
    # a pass's complete shader: the Common tab ahead of its code, its channels declared
    source = folder.source(folder.passes[1])
    assert source.index("vec3 tint()") < source.index("vec3 ground")
    assert "uniform sampler2D iChannel1;" in source


@pytest.mark.parametrize("form", ["list", "shader list", "bare"])
def test_the_apis_forms_of_the_json_read_alike(tmp_path: Path, form: str) -> None:
    data = json.loads((PROJECT / "shader.json").read_text())
    shader = data["Shader"]
    wrapped: Any = {"list": [data], "shader list": {"Shader": [shader]}, "bare": shader}[form]
    shutil.copy(PROJECT / "checker.png", tmp_path)
    (tmp_path / "api.json").write_text(json.dumps(wrapped))
    assert _summary(tmp_path / "api.json") == _summary(PROJECT / "shader.json")


def _edited(tmp_path: Path, change: Any) -> Path:
    data = json.loads((PROJECT / "shader.json").read_text())
    change(data["Shader"]["renderpass"])
    (tmp_path / "bad.json").write_text(json.dumps(data))
    return tmp_path / "bad.json"


@pytest.mark.parametrize(
    ("change", "says"),
    [
        (lambda p: p.pop(2), "has no Image pass"),
        (lambda p: p.pop(1), "iChannel0 reads Buffer A, which the project does not draw"),
        (lambda p: p[2]["inputs"][1].update(channel=7),
         r"Image.inputs\[1\].channel: 7 is not a channel"),
        (lambda p: p[2]["inputs"][1].update(type="cubemap"), "a cubemap is six pictures"),
        (lambda p: p[2]["inputs"][1].update(type="volume"), "a 'volume' channel is not bound"),
        (lambda p: p[2]["inputs"][1].update(channel=0), "two inputs on iChannel0"),
        (lambda p: p[2]["inputs"][1]["sampler"].update(wrap="mirror"), "sampler.wrap: 'mirror'"),
        (lambda p: p[1].update(code=3), r"renderpass\[1\].code: missing, or not a string"),
    ],
)  # fmt: skip
def test_a_project_glint_cannot_draw_gets_one_message(
    tmp_path: Path, change: Any, says: str
) -> None:
    shutil.copy(PROJECT / "checker.png", tmp_path)
    with pytest.raises(InputError, match=says):
        read_project(_edited(tmp_path, change))


def test_a_missing_picture_says_where_to_put_it(tmp_path: Path) -> None:
    bad = _edited(tmp_path, lambda p: None)  # checker.png not copied beside it
    with pytest.raises(InputError, match=r"put checker.png beside the JSON file or in .*media"):
        read_project(bad)
    (tmp_path / "media").mkdir()
    shutil.copy(PROJECT / "checker.png", tmp_path / "media")
    assert read_project(bad).passes[1].inputs[1].file == tmp_path / "media" / "checker.png"


def test_sound_passes_and_silent_inputs_do_not_stop_a_picture(tmp_path: Path) -> None:
    """ShaderToy's audio never reaches the picture: a sound pass is left out, and a keyboard or
    music input is black, as in ShaderToy with no key pressed and nothing playing."""

    def change(passes: list[dict[str, Any]]) -> None:
        sound = "vec2 mainSound(int s, float t) { return vec2(0); }"
        passes.append(
            {"type": "sound", "code": sound, "inputs": [], "outputs": [], "name": "Sound"}
        )
        passes[2]["inputs"].append({"id": 33, "type": "keyboard", "channel": 2})

    shutil.copy(PROJECT / "checker.png", tmp_path)
    project = read_project(_edited(tmp_path, change))
    assert [p.name for p in project.passes] == ["Buffer A", "Image"]
    assert project.passes[1].inputs[2].kind == "silent"


def test_not_shadertoy_json_and_bad_folders(tmp_path: Path) -> None:
    (tmp_path / "other.json").write_text('{"name": "a package.json"}')
    with pytest.raises(InputError, match="not ShaderToy's JSON"):
        read_project(tmp_path / "other.json")
    (tmp_path / "broken.json").write_text("{")
    with pytest.raises(InputError, match="not JSON"):
        read_project(tmp_path / "broken.json")
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(InputError, match="no tab here"):
        read_project(empty)
    shutil.copytree(PROJECT, tmp_path / "tabs")
    with (tmp_path / "tabs" / "channels.toml").open("a") as handle:
        handle.write('\n[buffer_c]\n0 = "buffer_a"\n')
    with pytest.raises(InputError, match=r"\[buffer_c\] is not a pass of the folder"):
        read_project(tmp_path / "tabs")


def test_validate_compiles_every_pass_of_a_project(tmp_path: Path) -> None:
    """`glint validate PROJECT`: each pass with the Common tab and its channels; an error under
    PROJECT:PASS:LINE, exit 1."""
    import subprocess
    import sys

    glint = [sys.executable, "-m", "glint.compiler.cli", "validate"]
    done = subprocess.run([*glint, str(PROJECT / "shader.json")], capture_output=True, text=True)
    assert done.returncode == 0 and "valid shadertoy project, 3 tabs" in done.stdout
    data = json.loads((PROJECT / "shader.json").read_text())
    image = data["Shader"]["renderpass"][2]
    image["code"] = image["code"].replace("vec3 ground", "vec3 ground = nowhere;\n    vec3 g2")
    (tmp_path / "bad.json").write_text(json.dumps(data))
    done = subprocess.run([*glint, str(tmp_path / "bad.json")], capture_output=True, text=True)
    assert done.returncode == 1 and f"{tmp_path / 'bad.json'}:Image:4:" in done.stdout


def test_a_project_written_as_json_reads_back_the_same(tmp_path: Path) -> None:
    """project_json (what compose --format shadertoy-json writes) for a project with a Common
    tab, a buffer feeding itself and a picture: read back, the same passes and inputs."""
    from glint.compiler.target.shadertoy_project import project_json

    project = read_project(PROJECT)
    shutil.copy(PROJECT / "checker.png", tmp_path)
    (tmp_path / "written.json").write_text(json.dumps(project_json(project, "trail")))
    back = read_project(tmp_path / "written.json")
    assert _summary(tmp_path / "written.json") == _summary(PROJECT)
    assert back.common == project.common
    assert [p.code for p in back.passes] == [p.code for p in project.passes]
