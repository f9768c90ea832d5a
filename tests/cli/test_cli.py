"""The `glint` command as a user runs it: output, exit codes, and one clear line on failure."""

from __future__ import annotations

import json
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from glint import compose

GLINT = [sys.executable, "-m", "glint.compiler.cli"]


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*GLINT, *args], capture_output=True, text=True, cwd=cwd, timeout=120)


def assert_one_clear_line(result: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in result.stderr
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert lines and lines[0].startswith("glint: ")


def test_compose_to_stdout_is_the_default_scene() -> None:
    result = run("compose")
    assert result.returncode == 0
    assert result.stdout == compose().text


def test_compose_to_file(tmp_path: Path) -> None:
    out = tmp_path / "shader.glsl"
    result = run("compose", "-o", str(out), "--target", "webgl2")
    assert result.returncode == 0, result.stderr
    assert out.read_text().startswith("#version 300 es")
    assert f"wrote {out}" in result.stderr


def test_compose_to_unwritable_path_fails_cleanly(tmp_path: Path) -> None:
    out = tmp_path / "missing-folder" / "shader.glsl"
    result = run("compose", "-o", str(out))
    assert result.returncode == 2
    assert_one_clear_line(result)
    assert "cannot write" in result.stderr and "choose a writable path" in result.stderr
    assert not out.parent.exists()


def _scene_with_geometry(tmp_path: Path, body: str) -> Path:
    """A scene whose distance function is the user's own file, holding `body`."""
    (tmp_path / "field.glsl").write_text(
        "float sceneDistance(vec3 p) {\n" + body + "    return length(p) - 1.0;\n}\n"
    )
    scene = tmp_path / "scene.toml"
    scene.write_text(
        '[geometry]\nfile = "field.glsl"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [0.8, 0.8, 0.8]\n"
        '[[lights]]\ntype = "directional"\ndirection = [0.3, 1.0, 0.2]\n'
    )
    return scene


@pytest.mark.skipif(shutil.which("glslangValidator") is None, reason="needs glslangValidator")
def test_compose_refuses_a_shader_that_does_not_compile_at_the_users_line(
    tmp_path: Path,
) -> None:
    """Issue 28: a type error in the scene's own GLSL was written with exit 0 and showed only
    when pasted. Compose now compiles what it writes: exit 1, the user's file and line, nothing
    written; --no-validate writes it anyway; a sound file composes as before."""
    scene = _scene_with_geometry(tmp_path, "    float wrong = vec2(1.0, 2.0);\n")
    out = tmp_path / "out.glsl"
    result = run("compose", str(scene), "-o", str(out))
    assert result.returncode == 1 and not out.exists()
    assert "Traceback" not in result.stderr
    assert f"{tmp_path / 'field.glsl'}:2:" in result.stderr or "field.glsl:2:" in result.stderr
    assert "cannot convert" in result.stderr and "--no-validate" in result.stderr
    for target in ("webgl2", "desktop"):
        assert run("compose", str(scene), "--target", target).returncode == 1
    forced = run("compose", str(scene), "-o", str(out), "--no-validate")
    assert forced.returncode == 0 and "vec2(1.0, 2.0)" in out.read_text()
    sound = _scene_with_geometry(tmp_path, "")
    assert run("compose", str(sound), "-o", str(out)).returncode == 0


def test_a_scene_file_that_reads_a_channel_is_an_error_at_its_line(tmp_path: Path) -> None:
    """Issue 28: iChannel0 read in the user's field sampled black with exit 0 (nothing is
    bound to it); now one clear error names the file, the line and the channel."""
    body = "    float bump = texture(iChannel0, p.xz).r;\n"
    scene = _scene_with_geometry(tmp_path, body)
    result = run("compose", str(scene), "--no-validate")
    assert result.returncode == 1
    assert_one_clear_line(result)
    assert "field.glsl:1: sceneDistance reads iChannel0" in result.stderr
    assert "sample black" in result.stderr


@pytest.mark.render
def test_compose_warns_of_a_lipschitz_too_small_and_an_id_nothing_maps(tmp_path: Path) -> None:
    """Issue 28: a field steeper than its declared lipschitz rendered holes, and an id that no
    material maps took another material, both with nothing said. Compose samples the field and
    warns of each, with the measured slope and a point; an honest scene says nothing."""
    (tmp_path / "bumpy.glsl").write_text(
        "float sceneDistance(vec3 p) {\n"
        "    return length(p) - 1.0 + 0.3 * sin(8.0 * p.x) * sin(8.0 * p.y) * sin(8.0 * p.z);\n"
        "}\n"
        "int sceneMaterial(vec3 p) {\n"
        "    return p.y > 0.5 ? 1 : p.y > -0.5 ? 3 : 2;\n"
        "}\n"
    )
    scene = tmp_path / "bumpy.toml"
    text = (
        '[geometry]\nfile = "bumpy.glsl"\nbounds = [[-1.5, -1.5, -1.5], [1.5, 1.5, 1.5]]\n'
        '[geometry.materials]\n1 = "m"\n3 = "n"\n'
        "[materials.m]\nalbedo = [0.8, 0.8, 0.8]\n[materials.n]\nalbedo = [0.2, 0.4, 0.8]\n"
        '[[lights]]\ntype = "directional"\ndirection = [0.3, 1.0, 0.2]\n'
    )
    scene.write_text(text)
    result = run("compose", str(scene), "-o", str(tmp_path / "out.glsl"))
    assert result.returncode == 0, result.stderr  # warnings: the shader is still written
    lipschitz = [line for line in result.stderr.splitlines() if "lipschitz = 1:" in line]
    assert len(lipschitz) == 1, result.stderr
    # |grad| reaches about 1 + 0.3 * 8 * sqrt(3) = 5.2 here; sampling finds at least 3
    slope = float(lipschitz[0].split("changes by ")[1].split()[0])
    assert 3.0 < slope < 5.3
    assert "sceneMaterial returns 2 near the surface" in result.stderr
    assert "returns 1" not in result.stderr and "returns 3" not in result.stderr
    # declared steep enough and every id mapped: not a word
    scene.write_text(
        text.replace("[geometry.materials]", "lipschitz = 6.0\n[geometry.materials]").replace(
            '1 = "m"', '1 = "m"\n2 = "m"'
        )
    )
    quiet = run("compose", str(scene), "-o", str(tmp_path / "out.glsl"))
    assert quiet.returncode == 0 and "warning" not in quiet.stderr, quiet.stderr


def test_bad_scene_exit_1_names_the_key(tmp_path: Path) -> None:
    scene = tmp_path / "bad.toml"
    scene.write_text(
        '[[objects]]\nshape = "sphere"\nradius = "big"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n"
    )
    result = run("compose", str(scene))
    assert result.returncode == 1
    assert_one_clear_line(result)
    assert "objects[0].radius" in result.stderr and "'big'" in result.stderr


def test_missing_scene_file(tmp_path: Path) -> None:
    result = run("compose", str(tmp_path / "nope.toml"))
    assert result.returncode == 1
    assert_one_clear_line(result)


def test_usage_error_exit_2() -> None:
    result = run("compose", "--variant", "shadow")
    assert result.returncode == 2
    assert_one_clear_line(result)
    assert run("frobnicate").returncode == 2


def test_validate_clean_and_broken(tmp_path: Path) -> None:
    good = tmp_path / "good.glsl"
    good.write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0, 1); }")
    result = run("validate", str(good))
    assert result.returncode == 0 and "valid shadertoy shader" in result.stdout

    bad = tmp_path / "bad.glsl"
    bad.write_text("void mainImage(out vec4 c, in vec2 p) {\n    c = texture2D(iChannel0, p);\n}\n")
    result = run("validate", str(bad))
    assert result.returncode == 1
    assert f"{bad}:2:" in result.stdout and "texture2D" in result.stdout


def test_validate_maps_composed_errors_to_the_snippet(tmp_path: Path) -> None:
    text = compose().text.replace("return a2 / (PI * d * d);", "return a2 / (PI * d * d)")
    shader = tmp_path / "broken.glsl"
    shader.write_text(text)
    result = run("validate", str(shader))
    assert result.returncode == 1
    ggx = Path("snippets/D/ggx.glsl").read_text().splitlines()
    line = next(i for i, t in enumerate(ggx, 1) if "return a2 / (PI * d * d);" in t)
    assert f"snippets/D/ggx.glsl:{line}" in result.stdout or f"snippets/D/ggx.glsl:{line + 1}" in (
        result.stdout
    )


def test_validate_missing_file() -> None:
    result = run("validate", "no/such/file.glsl")
    assert result.returncode == 1
    assert_one_clear_line(result)


@pytest.mark.render
def test_render_scene_writes_png_and_json(tmp_path: Path) -> None:
    out = tmp_path / "default.png"
    result = run(
        "render",
        "snippets/scenes/default.toml",
        "-o",
        str(out),
        "--size",
        "96x54",
        "--time",
        "1",
        "--json",
    )
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert report["nan"] == 0 and report["inf"] == 0
    assert (report["width"], report["height"]) == (96, 54)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.render
def test_render_nan_is_reported_with_exit_1(tmp_path: Path) -> None:
    shader = tmp_path / "nan.glsl"
    shader.write_text(
        "void mainImage(out vec4 c, in vec2 p) { c = vec4(sqrt(-1.0 - iTime), 0.0, 0.0, 1.0); }\n"
    )
    result = run("render", str(shader), "-o", str(tmp_path / "nan.png"), "--size", "8x8")
    assert result.returncode == 1
    assert "NaN pixels: 64" in result.stdout


@pytest.mark.render
def test_render_endless_loop_times_out(tmp_path: Path) -> None:
    shader = tmp_path / "loop.glsl"
    body = " ".join("x = sin(x + 1.0);" for _ in range(64))
    shader.write_text(
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    float x = p.x;\n"
        f"    for (int i = 0; i >= 0; i += int(iTime + 1.0)) {{ {body} }}\n"
        "    c = vec4(x);\n}\n"
    )
    result = run(
        "render", str(shader), "-o", str(tmp_path / "loop.png"), "--timeout", "3", "--size", "64x64"
    )
    assert result.returncode == 1
    assert_one_clear_line(result)
    assert "did not finish within" in result.stderr
    assert not (tmp_path / "loop.png").exists()


def test_catalog_json_is_a_stable_interface() -> None:
    result = run("catalog", "--json")
    assert result.returncode == 0, result.stderr
    entries = json.loads(result.stdout)
    by_id = {e["id"]: e for e in entries}
    for entry in entries:
        assert {"id", "slot", "provides", "requires", "signature", "file"} <= entry.keys()
        assert Path(entry["file"]).exists()
    assert by_id["D.ggx"]["signature"] == ["float distribution(float NoH, float a)"]
    assert by_id["D.ggx"]["provides"][0] == "distribution"


def test_a_reader_that_stops_early_is_not_an_error() -> None:
    # `glint catalog | head -0`: the reader is gone before glint writes a byte (closing our end
    # at once, while the child is still importing), so its first write meets a closed pipe.
    proc = subprocess.Popen([*GLINT, "catalog"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.close()
    error = proc.stderr.read().decode()
    assert proc.wait(timeout=60) == 0, error
    assert "internal error" not in error and "Traceback" not in error


# -o writes a regular file or standard output; anything else it refuses, and never replaces.


def test_compose_to_stdout_with_a_dash(tmp_path: Path) -> None:
    result = run("compose", "-o", "-", "--explain", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == compose().text  # the explanation went to stderr
    assert "wrote" not in result.stderr and result.stderr.strip()
    assert list(tmp_path.iterdir()) == []  # no file named "-"


def test_compose_into_the_null_device(null_device: str) -> None:
    result = run("compose", "-o", null_device)
    assert result.returncode == 0, result.stderr
    assert Path(null_device).is_char_device()


def test_split_into_a_link_to_the_null_device_writes_nothing_beside_it(
    tmp_path: Path, null_device: str
) -> None:
    (tmp_path / "out.glsl").symlink_to(null_device)
    result = run("compose", "--split", "common", "-o", str(tmp_path / "out.glsl"))
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.glsl"]  # no out.common.glsl
    assert Path(null_device).is_char_device()


def test_split_to_stdout_is_a_usage_error() -> None:
    result = run("compose", "--split", "common", "-o", "-")
    assert result.returncode == 2
    assert_one_clear_line(result)


@pytest.mark.parametrize(
    ("kind", "says"),
    [("fifo", "it is a FIFO"), ("folder", "it is a folder"), ("read-only", "it is read-only")],
)
def test_compose_refuses_what_is_not_a_writable_file(tmp_path: Path, kind: str, says: str) -> None:
    out = tmp_path / "out.glsl"
    if kind == "fifo":
        os.mkfifo(out)  # opening it to write would hang until a reader came
    elif kind == "folder":
        out.mkdir()
    else:
        out.write_text("mine\n")
        out.chmod(0o444)
    result = run("compose", "-o", str(out))  # run() gives up after a timeout rather than hang
    assert result.returncode == 2
    assert_one_clear_line(result)
    assert f"glint: cannot write {out}: {says}" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert [p.name for p in tmp_path.iterdir()] == ["out.glsl"]
    if kind == "fifo":
        assert stat.S_ISFIFO(out.lstat().st_mode)
    elif kind == "read-only":
        assert out.read_text() == "mine\n"


@pytest.mark.render
def test_render_png_to_stdout(tmp_path: Path) -> None:
    shader = tmp_path / "red.glsl"
    shader.write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0, 0.0, 0.0, 1.0); }\n")
    result = subprocess.run(
        [*GLINT, "render", str(shader), "-o", "-", "--size", "8x8", "--json"],
        capture_output=True, cwd=tmp_path, timeout=120,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith(b"\x89PNG\r\n\x1a\n")
    assert json.loads(result.stderr)["nan"] == 0  # the report beside the PNG, on stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["red.glsl"]


@pytest.mark.render
def test_render_into_the_null_device(tmp_path: Path, null_device: str) -> None:
    shader = tmp_path / "red.glsl"
    shader.write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0, 0.0, 0.0, 1.0); }\n")
    result = run("render", str(shader), "-o", null_device, "--size", "8x8")
    assert result.returncode == 0, result.stderr
    assert Path(null_device).is_char_device()


def test_mesh_programs_into_a_link_to_the_null_device_write_nothing_beside_it(
    tmp_path: Path, null_device: str
) -> None:
    (tmp_path / "out").symlink_to(null_device)
    scene = "snippets/scenes/eight_models.toml"
    result = run("compose", scene, "--target", "mesh-webgl2", "-o", str(tmp_path / "out"))
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no out.frag, out.vert
    assert Path(null_device).is_char_device()


def test_a_message_cannot_drive_the_terminal(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A file name with an escape sequence or a carriage return, quoted in an error, is shown
    escaped: it can neither recolour the terminal nor overwrite the line it is on."""
    from glint.compiler.cli import main

    name = str(tmp_path / "a\x1b[2J\rfake.toml")
    assert main(["compose", name]) == 1
    err = capsys.readouterr().err
    assert "\x1b" not in err and "\r" not in err
    assert "\\x1b[2J\\rfake.toml" in err


@pytest.mark.parametrize(
    "option, value, message",
    [
        ("--timeout", "inf", "--timeout: must be more than 0 and at most 3600 seconds, got 'inf'"),
        ("--timeout", "nan", "--timeout: must be more than 0 and at most 3600 seconds, got 'nan'"),
        ("--timeout", "1e308", "--timeout: must be more than 0 and at most 3600 seconds"),
        ("--timeout", "0", "--timeout: must be more than 0 and at most 3600 seconds, got '0'"),
        ("--timeout", "-1", "--timeout: must be more than 0 and at most 3600 seconds, got '-1'"),
        ("--timeout", "3601", "--timeout: must be more than 0 and at most 3600 seconds"),
        ("--timeout", "soon", "--timeout: expected a number, got 'soon'"),
        ("--time", "inf", "--time: must be a finite number from -3.4e+38 to 3.4e+38"),
        ("--time", "nan", "--time: must be a finite number"),
        ("--time", "1e39", "--time: must be a finite number"),
        ("--frame", "99999999999", "--frame: must be from 0 to 2147483647"),
        ("--frame", "-1", "--frame: must be from 0 to 2147483647"),
        ("--frame", "1.5", "--frame: expected a whole number, got '1.5'"),
        ("--mouse", "inf,0,0,0", "--mouse: each of x,y,z,w must be a finite number"),
        ("--mouse", "0,nan,0,0", "--mouse: each of x,y,z,w must be a finite number"),
        ("--mouse", "1,2", "--mouse: expected four numbers x,y,z,w, got '1,2'"),
        ("--size", "0x5", "--size: width and height must be 1..8192, got '0x5'"),
        ("--size", "-5x5", "--size: width and height must be 1..8192, got '-5x5'"),
        ("--size", "8193x8", "--size: width and height must be 1..8192"),
        ("--size", "8x", "--size: expected WxH such as 640x360, got '8x'"),
    ],
)
def test_render_options_out_of_range_are_usage_errors(
    tmp_path: Path, option: str, value: str, message: str
) -> None:
    shader = tmp_path / "flat.glsl"
    shader.write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n")
    out = tmp_path / "flat.png"
    result = run("render", str(shader), "-o", str(out), f"{option}={value}")
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr
    assert f"glint render: error: argument {message}" in result.stderr
    assert not out.exists()


def test_render_refuses_a_size_past_the_memory_it_may_use(tmp_path: Path) -> None:
    """8192x8192 needs about 4.6 GB; under a 1 GB data limit (ulimit -d) it is refused before
    anything is drawn, with what it needs and what there is."""
    shader = tmp_path / "flat.glsl"
    shader.write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n")
    out = tmp_path / "big.png"
    command = " ".join([*GLINT, "render", str(shader), "-o", str(out), "--size", "8192x8192"])
    result = subprocess.run(
        ["sh", "-c", f"ulimit -d 1048576 && exec {command}"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 2, result.stderr
    assert (
        "argument --size: 8192x8192 needs about 4.6 GB of memory to render, and only 1.0 GB is "
        "available here; choose a smaller size" in result.stderr
    )
    assert not out.exists()


@pytest.mark.render
def test_render_json_is_json_when_pixels_are_nan(tmp_path: Path) -> None:
    """A channel with no finite value has no mean: null in the report, never NaN (which no JSON
    reader accepts)."""
    shader = tmp_path / "nan.glsl"
    shader.write_text(
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    c = vec4(sqrt(-1.0 - iTime), 1.0 / (iTime - iTime), 0.25, 1.0);\n}\n"
    )
    result = run("render", str(shader), "-o", str(tmp_path / "nan.png"), "--size", "8x4", "--json")
    assert result.returncode == 1, result.stderr

    def refuse(constant: str) -> None:
        raise AssertionError(f"{constant} in the JSON report")

    report = json.loads(result.stdout, parse_constant=refuse)
    assert (report["nan"], report["inf"]) == (32, 32)
    assert report["mean"] == [None, None, 0.25] and report["std"] == [None, None, 0.0]
    assert report["finite_min"] == report["finite_max"] == 0.25
