"""glint lint on a ShaderToy project (its JSON, or a folder of tabs): every pass with the
project's Common tab in front and its channels typed by what they read, findings under
`PROJECT:PASS:LINE:COLUMN`."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

PROJECT = Path(__file__).resolve().parents[1] / "corpus" / "projects" / "feedback"
GLINT = [sys.executable, "-m", "glint.compiler.cli"]


def _lint(*paths: Path | str) -> subprocess.CompletedProcess[str]:
    command = [*GLINT, "lint", "--no-cache", "--format", "concise", *map(str, paths)]
    return subprocess.run(command, capture_output=True, text=True)


def test_a_project_lints_clean_with_its_common_tab_and_not_without(tmp_path: Path) -> None:
    """Buffer A calls tint() from the Common tab: as a project it is clean; the same tab linted
    as a loose file (no Common tab) gets an error that is not the author's."""
    for project in (PROJECT, PROJECT / "shader.json"):
        done = _lint(project)
        assert done.returncode == 0, done.stdout + done.stderr
    shutil.copy(PROJECT / "buffer_a.glsl", tmp_path / "loose.glsl")
    loose = _lint(tmp_path / "loose.glsl")
    assert loose.returncode == 1 and "'tint'" in loose.stdout


def test_a_finding_names_the_project_and_the_pass(tmp_path: Path) -> None:
    data = json.loads((PROJECT / "shader.json").read_text())
    buffer = data["Shader"]["renderpass"][1]
    buffer["code"] = buffer["code"].replace("* 0.95;", "* 0.95 + wobble;")
    broken = tmp_path / "broken.json"
    broken.write_text(json.dumps(data))
    done = _lint(broken)
    line = next(i for i, text in enumerate(buffer["code"].split("\n"), 1) if "wobble" in text)
    assert done.returncode == 1
    assert f"{broken}:Buffer A:{line}:" in done.stdout and "'wobble'" in done.stdout


def test_a_cubemap_channel_is_typed_as_one(tmp_path: Path) -> None:
    """A pass that samples a cubemap with a direction: a sampler2D would make it an error;
    the project's input says samplerCube. No picture is needed to lint."""
    data = json.loads((PROJECT / "shader.json").read_text())
    image = data["Shader"]["renderpass"][2]
    image["inputs"][1].update(type="cubemap", src="/media/a/sky.jpg")
    image["code"] = image["code"].replace(
        "texture(iChannel1, uv * 2.0).rgb", "texture(iChannel1, vec3(uv, 1.0)).rgb"
    )
    (tmp_path / "cube.json").write_text(json.dumps(data))
    done = _lint(tmp_path / "cube.json")
    assert done.returncode == 0, done.stdout + done.stderr


def test_fix_is_refused_on_a_project() -> None:
    done = subprocess.run([*GLINT, "lint", "--fix", str(PROJECT)], capture_output=True, text=True)
    assert done.returncode == 2 and "--fix rewrites files" in done.stderr


def test_sarif_names_the_pass_and_a_folder_its_tab_file(tmp_path: Path) -> None:
    """In SARIF a JSON pass's finding is at the JSON file with the pass as a logical location;
    a folder's tab is reported at its own file, whose lines they are."""
    data = json.loads((PROJECT / "shader.json").read_text())
    buffer = data["Shader"]["renderpass"][1]
    buffer["code"] = buffer["code"].replace("* 0.95;", "* 0.95 + wobble;")
    (tmp_path / "broken.json").write_text(json.dumps(data))
    command = [*GLINT, "lint", "--no-cache", "--format", "sarif", str(tmp_path / "broken.json")]
    log = json.loads(subprocess.run(command, capture_output=True, text=True).stdout)
    location = log["runs"][0]["results"][0]["locations"][0]
    assert location["physicalLocation"]["artifactLocation"]["uri"] == str(tmp_path / "broken.json")
    assert location["logicalLocations"][0]["name"] == "Buffer A"
    folder = tmp_path / "tabs"
    shutil.copytree(PROJECT, folder)
    tab = folder / "buffer_a.glsl"
    tab.write_text(tab.read_text().replace("* 0.95;", "* 0.95 + wobble;"))
    done = _lint(folder)
    assert done.returncode == 1 and f"{tab}:5:" in done.stdout
