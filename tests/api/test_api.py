"""The Python API (`import glint`) runs what the `glint` command runs: the same shader text, the
same error messages, the same findings, the real renderer. No mocks."""

from __future__ import annotations

import io
import json
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from PIL import Image as PILImage

import glint
from glint.compiler.errors import InputError
from glint.compiler.render import render as render_rgba
from glint.compiler.scene.model import load_scene

ROOT = Path(__file__).resolve().parents[2]
DEFAULT = ROOT / "snippets" / "scenes" / "default.toml"
MISTAKE = ROOT / "tests" / "corpus" / "lint_mistakes" / "iglobaltime.glsl"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
OLD_TIME = """void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(vec3(0.5 + 0.5 * cos(iGlobalTime)), 1.0);
}
"""
BAD_SCENE = """
[[objects]]
shape = "sphere"
material = "red"

[materials.red]
albedo = [0.8, 0.1, 0.1]

[[lights]]
type = "directional"
direction = [1.0, 1.0, 1.0]
color = [1.0, "x", 1.0]
"""
needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator is not installed"
)


def cli(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
    )


def test_import_glint_loads_nothing_heavy() -> None:
    code = (
        "import sys, glint; "
        "print(sorted(m for m in ('numpy', 'moderngl', 'pydantic', 'lark', 'glint.lint') "
        "if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"


def test_the_public_names() -> None:
    assert set(glint.__all__) >= {"compose", "render", "lint_shader", "catalog", "Shader"}
    assert glint.InputError is InputError  # the compiler's own error types, not copies
    assert issubclass(glint.EnvironmentProblem, glint.GlintError)
    assert glint.__version__.count(".") >= 1


@pytest.mark.parametrize(
    "flags, kwargs",
    [
        ([], {}),
        (
            ["--tier", "fast", "--target", "webgl2", "--variant", "shadow=hard"],
            {"tier": "fast", "target": "webgl2", "variants": {"shadow": "hard"}},
        ),
    ],
)
def test_compose_writes_what_the_command_writes(
    tmp_path: Path, flags: list[str], kwargs: dict[str, object]
) -> None:
    out = tmp_path / "shader.glsl"
    done = cli("compose", str(DEFAULT), "-o", str(out), *flags)
    assert done.returncode == 0, done.stderr
    shader = glint.compose(str(DEFAULT), **kwargs)  # type: ignore[arg-type]
    assert shader.text == out.read_text(encoding="utf-8")
    assert f"{len(shader.snippets)} snippets, tier {shader.tier}" in done.stderr


def test_compose_takes_a_dict_a_scene_or_nothing() -> None:
    expected = glint.compose(DEFAULT).text
    data = tomllib.loads(DEFAULT.read_text(encoding="utf-8"))
    assert glint.compose(data).text == expected
    assert glint.compose(load_scene(DEFAULT)).text == expected
    assert glint.compose().text == expected  # the embedded default scene is this file


def test_explain_is_what_the_command_prints() -> None:
    done = cli("compose", str(DEFAULT), "--explain", "--tier", "reference")
    assert done.returncode == 0, done.stderr
    assert glint.compose(DEFAULT, tier="reference").explain() == done.stdout


def test_an_invalid_scene_raises_the_message_the_command_prints(tmp_path: Path) -> None:
    scene = tmp_path / "scene.toml"
    scene.write_text(BAD_SCENE, encoding="utf-8")
    done = cli("compose", str(scene))
    assert done.returncode == 1
    with pytest.raises(glint.InputError) as caught:
        glint.compose(scene)
    assert done.stderr == f"glint: {caught.value.message}\n"
    assert "lights[0].color[1]: input should be a valid number (got 'x')" in done.stderr
    # A dict is checked the same way; its messages name it <scene>.
    with pytest.raises(glint.InputError) as caught:
        glint.compose(tomllib.loads(BAD_SCENE))
    assert f"glint: {caught.value.message}\n" == done.stderr.replace(str(scene), "<scene>")


def test_bad_arguments_are_usage_errors() -> None:
    with pytest.raises(glint.UsageError, match="tier: unknown value 'best'"):
        glint.compose(tier="best")
    with pytest.raises(glint.UsageError, match="target: unknown value"):
        glint.compose(target="vulkan")
    with pytest.raises(glint.UsageError, match="budget"):
        glint.compose(budget=-1.0)
    with pytest.raises(glint.UsageError, match="size"):
        glint.render(OLD_TIME, size=(0, 36))
    with pytest.raises(glint.UsageError, match="target is webgl2"):
        glint.render(glint.compose(target="webgl2"))
    with pytest.raises(glint.InputError, match="unknown variant 'nope'"):
        glint.compose(variants={"shadow": "nope"})
    with pytest.raises(glint.InputError, match=r"^missing\.glsl: no such file$"):
        glint.render("missing.glsl")


def test_a_shader_shows_itself() -> None:
    shader = glint.compose(DEFAULT)
    assert str(shader) == shader.text
    assert repr(shader).startswith("<glint.Shader scene 'default', shadertoy target, tier bal")
    page = shader._repr_html_()
    assert page.startswith("<div><strong>glint shader</strong>: scene &#x27;default&#x27;")
    assert "void mainImage(out vec4 fragColor, in vec2 fragCoord)" in page
    assert "<pre" in page and "<code>" in page and "</code></pre></div>" in page


def test_save_writes_the_text(tmp_path: Path) -> None:
    shader = glint.compose(DEFAULT, tier="fast")
    path = shader.save(tmp_path / "fast.glsl")
    assert path.read_text(encoding="utf-8") == shader.text


@needs_glslang
def test_validate_runs_glslang() -> None:
    assert glint.compose(DEFAULT).validate() == []


@pytest.mark.render
def test_render_draws_with_the_project_renderer() -> None:
    shader = glint.compose(DEFAULT)
    image = glint.render(shader, size=(64, 36), time=1.0)
    assert image.pixels.dtype == np.float32 and image.pixels.shape == (36, 64, 3)
    assert np.isfinite(image.pixels).all() and image.finite
    assert image.stats["nan"] == 0 and image.stats["inf"] == 0
    assert (image.width, image.height, image.time) == (64, 36, 1.0)
    assert np.asarray(image) is image.pixels
    # The same pixels as the renderer the command uses.
    assert np.array_equal(image.pixels, render_rgba(shader.text, 64, 36, time=1.0)[:, :, :3])
    png = image._repr_png_()
    assert png.startswith(PNG_SIGNATURE)
    with PILImage.open(io.BytesIO(png)) as decoded:
        assert decoded.size == (64, 36) and decoded.mode == "RGB"
    assert "64x36" in repr(image) and "NaN pixels 0" in repr(image)


@pytest.mark.render
def test_render_takes_code_a_file_or_a_scene(tmp_path: Path) -> None:
    code = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(0.25, 0.5, 1.0, 1.0);\n}\n"
    image = glint.render(code, size=(8, 4))
    assert np.allclose(image.pixels, [0.25, 0.5, 1.0])
    path = tmp_path / "flat.glsl"
    path.write_text(code, encoding="utf-8")
    assert np.array_equal(glint.render(path, size=(8, 4)).pixels, image.pixels)
    assert glint.render(str(DEFAULT), size=(16, 9)).pixels.shape == (9, 16, 3)
    saved = image.save(tmp_path / "flat.png")
    assert saved.read_bytes().startswith(PNG_SIGNATURE)


@pytest.mark.render
def test_a_shader_the_driver_rejects_is_an_input_error() -> None:
    broken = "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(undefinedThing);\n}\n"
    with pytest.raises(glint.InputError, match="the OpenGL driver rejected the shader"):
        glint.render(broken, size=(8, 4))


def test_lint_finds_a_mistake_and_passes_clean_code() -> None:
    findings = glint.lint_shader(OLD_TIME)
    assert [(f.code, f.line, f.file) for f in findings] == [("P004", 2, "<input>")]
    assert findings[0].fix is not None
    assert glint.lint_shader(OLD_TIME.replace("iGlobalTime", "iTime")) == []
    assert glint.lint_shader(OLD_TIME, ignore="P004", glslang=False) == []


def test_lint_of_a_file_is_what_the_command_reports() -> None:
    done = cli("lint", str(MISTAKE), "--format", "json", "--no-cache")
    assert done.returncode == 1, done.stderr
    findings = glint.lint_shader(MISTAKE)
    assert [f.as_json() for f in findings] == json.loads(done.stdout)
    folder = glint.lint_shader(MISTAKE.parent)
    assert {f.file for f in folder} > {str(MISTAKE)}


def test_lint_errors_are_the_command_s() -> None:
    with pytest.raises(glint.UsageError, match="unknown rule code or prefix 'XX9'"):
        glint.lint_shader(OLD_TIME, select=["xx9"])
    with pytest.raises(glint.UsageError, match="no such file or directory"):
        glint.lint_shader("missing.glsl")


def test_a_composed_shader_lints_clean() -> None:
    assert glint.lint_shader(glint.compose(DEFAULT, target="desktop"), glslang=False) == []


def test_catalog_lookup() -> None:
    catalog = glint.catalog()
    ggx = catalog["D.ggx"]
    assert (ggx.slot, ggx.variant, ggx.file) == ("D", "ggx", "snippets/D/ggx.glsl")
    assert "float distribution(float NoH, float a) {" in ggx.source
    assert ggx.source in (ROOT / ggx.file).read_text(encoding="utf-8")
    assert "D.ggx" in catalog and "D.nope" not in catalog and catalog.get("D.nope") is None
    assert ggx in catalog.slot("D") and len(catalog) == len(list(catalog))
    with pytest.raises(KeyError, match="did you mean D.ggx"):
        catalog["D.ggz"]
    assert ggx._repr_markdown_().startswith("**D.ggx** (snippets/D/ggx.glsl)")
    done = cli("catalog", "show", "D.ggx")
    assert ggx.standalone() == done.stdout


def test_the_api_from_a_fresh_interpreter(tmp_path: Path) -> None:
    code = (
        "import glint\n"
        "shader = glint.compose(tier='fast')\n"
        "print(shader.tier, len(shader.snippets) > 0, shader.text.startswith('// glint'))\n"
        "print([f.code for f in glint.lint_shader(open('shader.glsl').read())])\n"
        "print(glint.catalog()['D.ggx'].slot)\n"
        "try:\n"
        "    glint.compose('missing.toml')\n"
        "except glint.InputError as exc:\n"
        "    print(exc.message)\n"
    )
    (tmp_path / "shader.glsl").write_text(OLD_TIME, encoding="utf-8")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == [
        "fast True True",
        "['P004']",
        "D",
        "missing.toml: no such scene file",
    ]


@pytest.mark.render
def test_in_a_notebook_cell() -> None:
    """A real Jupyter kernel runs the API in notebook cells: a Shader shows as HTML (its header
    and code), an Image as a PNG."""
    import base64

    import nbformat
    from nbclient import NotebookClient

    notebook = nbformat.v4.new_notebook()
    notebook.cells = [
        nbformat.v4.new_code_cell("import glint\nshader = glint.compose()\nshader"),
        nbformat.v4.new_code_cell("glint.render(shader, size=(32, 18), time=1.0)"),
    ]
    NotebookClient(notebook, timeout=120, kernel_name="python3").execute()
    shown = [cell.outputs[-1]["data"] for cell in notebook.cells]
    assert "glint shader" in shown[0]["text/html"] and "mainImage" in shown[0]["text/html"]
    assert base64.b64decode(shown[1]["image/png"]).startswith(PNG_SIGNATURE)
