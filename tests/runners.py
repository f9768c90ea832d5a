"""ShaderToy runners other than glint's own, for the portability test
(tests/e2e/test_portability.py): each renders Image-tab shaders (what `glint compose` writes for
the shadertoy target) to float RGB images, row 0 at the top, as `glint render` gives them.

- WebGL2 in Debian's Chromium (SwiftShader), through Playwright: one page draws every shader
  (its complete webgl2 fragment shader, `glint compose --target webgl2`) into a float
  framebuffer and reads it back.
- wgpu-shadertoy (GLSL through naga, on Mesa's lavapipe Vulkan driver), offscreen: one child
  process renders every shader, under a wall-clock limit, so that a driver that hangs or crashes
  costs the test a failure rather than the session.

`make test` installs both (chromium, mesa-vulkan-drivers; wgpu-shadertoy in the dev extra).
Run as a script, this module is that child process: `python runners.py wgpu JOB.json`.
"""

from __future__ import annotations

import base64
import contextlib
import glob
import importlib.util
import json
import os
import signal
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from PIL import Image

from glint.compiler.target.shadertoy_project import Project

if TYPE_CHECKING:
    from playwright.sync_api import Browser

# wgpu-py and rendercanvas: draw offscreen, never look for a display.
WGPU_ENV = {"WGPU_FORCE_OFFSCREEN": "true", "RENDERCANVAS_FORCE_OFFSCREEN": "1"}
# Where Debian's mesa-vulkan-drivers puts lavapipe's Vulkan ICD manifest.
LAVAPIPE_ICDS = "/usr/share/vulkan/icd.d/lvp_icd*.json"
# ShaderToy's iDate for every runner: the one `glint render` uses (year, month from 0, day, s).
DATE = (2026.0, 0.0, 1.0, 0.0)
TIME_DELTA = 1.0 / 60.0  # glint render's iTimeDelta


class RunnerFailure(Exception):
    """A runner could not render a shader: it did not compile, crashed or ran out of time."""


# --- wgpu-shadertoy -------------------------------------------------------------------------


def wgpu_missing() -> str | None:
    """Why wgpu-shadertoy cannot run here (the package or lavapipe is missing), or None."""
    if importlib.util.find_spec("wgpu_shadertoy") is None:
        return "wgpu-shadertoy is not installed"
    if not glob.glob(LAVAPIPE_ICDS):
        return "Mesa's lavapipe Vulkan driver (mesa-vulkan-drivers) is not installed"
    return None


Pictures = dict[int, np.ndarray]  # channel -> the picture file's RGBA8, top row first


def render_wgpu(
    shaders: Sequence[str],
    width: int,
    height: int,
    time: float,
    timeout: float = 120.0,
    pictures: Sequence[Pictures] | None = None,
) -> list[np.ndarray | RunnerFailure]:
    """Render each Image-tab shader with wgpu-shadertoy offscreen, in one child process: for each
    shader its float32 H x W x 3 image in [0, 1] (row 0 at the top) or why it failed. Raises
    RunnerFailure when the child process itself fails (no Vulkan adapter, an import error).
    `pictures`: per shader, the pictures bound to its channels (repeating, as ShaderToy)."""
    with tempfile.TemporaryDirectory(prefix="glint-wgpu-") as folder:
        bound = []
        for index, channels in enumerate(pictures or [{}] * len(shaders)):
            files = {}
            for unit, data in channels.items():
                path = Path(folder) / f"picture-{index}-{unit}.npy"
                np.save(path, data)
                files[str(unit)] = str(path)
            bound.append(files)
        job = {"shaders": list(shaders), "width": width, "height": height, "time": time,
               "pictures": bound}  # fmt: skip
        job_path = Path(folder) / "job.json"
        job_path.write_text(json.dumps({**job, "output": folder}))
        process = subprocess.Popen(
            [sys.executable, __file__, "wgpu", str(job_path)],
            env=os.environ | WGPU_ENV,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            start_new_session=True,  # killed with anything it started
        )
        try:
            output, _ = process.communicate(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGKILL)
            output, _ = process.communicate()
            timed_out = True
        log = output.decode(errors="replace").strip()[-2000:]
        results: list[np.ndarray | RunnerFailure] = []
        for index in range(len(shaders)):
            image_path = Path(folder) / f"{index}.npy"
            error_path = Path(folder) / f"{index}.error"
            if image_path.is_file():
                results.append(np.load(image_path))
            elif error_path.is_file():
                results.append(RunnerFailure(error_path.read_text()))
            elif timed_out:
                results.append(RunnerFailure(f"wgpu-shadertoy ran past {timeout:.0f} s"))
            else:
                results.append(RunnerFailure(f"wgpu-shadertoy's process died:\n{log}"))
        if (
            process.returncode
            and not timed_out
            and not any(isinstance(r, np.ndarray) for r in results)
        ):
            raise RunnerFailure(f"wgpu-shadertoy failed (exit {process.returncode}):\n{log}")
        return results


def _wgpu_worker(job_path: str) -> int:
    """The child process: render each shader of the job; write I.npy or I.error for each."""
    job = json.loads(Path(job_path).read_text())
    output = Path(job["output"])
    from wgpu_shadertoy import Shadertoy
    from wgpu_shadertoy.inputs import ShadertoyChannelTexture

    size = (job["width"], job["height"])
    for index, code in enumerate(job["shaders"]):
        files = job.get("pictures", [{}] * len(job["shaders"]))[index]
        # channel by channel, black where nothing is bound; flipped (vflip) as ShaderToy does
        inputs = [
            ShadertoyChannelTexture(np.load(files[str(unit)]), wrap="repeat", vflip=True)
            if str(unit) in files
            else ShadertoyChannelTexture()
            for unit in range(4)
        ] if files else []  # fmt: skip
        try:
            shadertoy = Shadertoy(
                code, resolution=size, shader_type="glsl", offscreen=True, inputs=inputs
            )
            frame = shadertoy.snapshot(
                time_float=job["time"],
                time_delta=TIME_DELTA,
                frame=0,
                framerate=60.0,
                mouse_pos=(0.0, 0.0, 0.0, 0.0),
                date=DATE,
            )
        except Exception as exc:  # a shader naga or the driver rejects: that shader fails
            (output / f"{index}.error").write_text(f"{type(exc).__name__}: {exc}")
            continue
        np.save(output / f"{index}.npy", _pixels(shadertoy, frame))
    return 0


def _pixels(shadertoy: Any, frame: Any) -> np.ndarray:
    """A snapshot as float32 RGB in [0, 1]: the canvas texture read back top row first, in its
    format's channel order (rgba8unorm here, bgra8unorm on some drivers)."""
    pixels = np.asarray(frame)[:, :, :3]
    if shadertoy._format.startswith("bgra"):
        pixels = pixels[:, :, ::-1]
    return pixels.astype(np.float32) / 255.0


# --- WebGL2 in Chromium ---------------------------------------------------------------------

_PAGE = """<!doctype html><html><body><canvas id="c"></canvas><script>
function renderAll(shaders, width, height, time, date, pictures) {
  const canvas = document.getElementById("c");
  canvas.width = width; canvas.height = height;
  const gl = canvas.getContext("webgl2", {antialias: false});
  if (!gl) return {error: "no WebGL2 context"};
  const float = gl.getExtension("EXT_color_buffer_float") !== null;
  const target = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texStorage2D(gl.TEXTURE_2D, 1, float ? gl.RGBA32F : gl.RGBA8, width, height);
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  gl.viewport(0, 0, width, height);
  // Unused iChannels sample a black texture, as in glint render.
  const black = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, black);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                new Uint8Array([0, 0, 0, 255]));
  for (let unit = 0; unit < 4; unit++) {
    gl.activeTexture(gl.TEXTURE0 + unit); gl.bindTexture(gl.TEXTURE_2D, black);
  }
  const vertex = gl.createShader(gl.VERTEX_SHADER);
  gl.shaderSource(vertex, "#version 300 es\\nvoid main() {\\n" +
    "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\\n" +
    "  gl_Position = vec4(p, 0.0, 1.0);\\n}\\n");
  gl.compileShader(vertex);
  const results = [];
  for (let index = 0; index < shaders.length; index++) {
    const source = shaders[index];
    // the shader's pictures, as ShaderToy binds one: bottom row at v = 0 (the rows come
    // bottom first), mipmapped, repeating; black elsewhere
    const sizes = new Float32Array(12).fill(1);
    const made = [];
    for (let unit = 0; unit < 4; unit++) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      const picture = pictures[index][unit];
      if (!picture) { gl.bindTexture(gl.TEXTURE_2D, black); continue; }
      const texture = gl.createTexture();
      made.push(texture);
      gl.bindTexture(gl.TEXTURE_2D, texture);
      const bytes = Uint8Array.from(atob(picture.data), (c) => c.charCodeAt(0));
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, picture.width, picture.height, 0, gl.RGBA,
                    gl.UNSIGNED_BYTE, bytes);
      gl.generateMipmap(gl.TEXTURE_2D);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
      sizes.set([picture.width, picture.height, 1], unit * 3);
    }
    const fragment = gl.createShader(gl.FRAGMENT_SHADER);
    gl.shaderSource(fragment, source);
    gl.compileShader(fragment);
    if (!gl.getShaderParameter(fragment, gl.COMPILE_STATUS)) {
      results.push({error: "compile: " + gl.getShaderInfoLog(fragment)});
      gl.deleteShader(fragment);
      continue;
    }
    const program = gl.createProgram();
    gl.attachShader(program, vertex); gl.attachShader(program, fragment);
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
      results.push({error: "link: " + gl.getProgramInfoLog(program)});
      continue;
    }
    gl.useProgram(program);
    const u = (name) => gl.getUniformLocation(program, name);
    gl.uniform3f(u("iResolution"), width, height, 1);
    gl.uniform1f(u("iTime"), time);
    gl.uniform1f(u("iTimeDelta"), 1 / 60);
    gl.uniform1i(u("iFrame"), 0);
    gl.uniform1f(u("iFrameRate"), 60);
    gl.uniform4f(u("iMouse"), 0, 0, 0, 0);
    gl.uniform4f(u("iDate"), date[0], date[1], date[2], date[3]);
    gl.uniform1fv(u("iChannelTime"), [time, time, time, time]);
    gl.uniform3fv(u("iChannelResolution"), sizes);
    gl.uniform1f(u("iSampleRate"), 44100);
    for (let unit = 0; unit < 4; unit++) gl.uniform1i(u("iChannel" + unit), unit);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    const pixels = float ? new Float32Array(width * height * 4)
                         : new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, float ? gl.FLOAT : gl.UNSIGNED_BYTE, pixels);
    const bytes = new Uint8Array(pixels.buffer);
    let text = "";
    for (let i = 0; i < bytes.length; i += 0x8000) {
      text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    }
    results.push({float: float, data: btoa(text)});
    gl.deleteProgram(program); gl.deleteShader(fragment);
    made.forEach((texture) => gl.deleteTexture(texture));
  }
  return {results: results, renderer: gl.getParameter(gl.RENDERER)};
}
</script></body></html>"""


def render_webgl2(
    browser: Browser,
    shaders: Sequence[str],
    width: int,
    height: int,
    time: float,
    pictures: Sequence[Pictures] | None = None,
) -> list[np.ndarray | RunnerFailure]:
    """Draw each complete WebGL2 fragment shader (ES 3.00 with ShaderToy's uniforms and a main,
    the webgl2 target) in one page of `browser`: for each its float32 H x W x 3 image, row 0 at
    the top, or why it failed. `pictures`: per shader, the pictures bound to its channels."""
    sent = [
        {
            str(unit): {
                "width": data.shape[1],
                "height": data.shape[0],
                "data": base64.b64encode(np.ascontiguousarray(data[::-1]).tobytes()).decode(),
            }
            for unit, data in channels.items()
        }
        for channels in (pictures or [{}] * len(shaders))
    ]
    context = browser.new_context()
    try:
        page = context.new_page()
        page.set_content(_PAGE)
        answer: dict[str, Any] = page.evaluate(
            "([s, w, h, t, d, p]) => renderAll(s, w, h, t, d, p)",
            [list(shaders), width, height, time, list(DATE), sent],
        )
    finally:
        context.close()
    if "error" in answer:
        raise RunnerFailure(f"Chromium: {answer['error']}")
    images: list[np.ndarray | RunnerFailure] = []
    for result in answer["results"]:
        if "error" in result:
            images.append(RunnerFailure(f"WebGL2 ({answer['renderer']}): {result['error']}"))
            continue
        raw = base64.b64decode(result["data"])
        if result["float"]:
            pixels = np.frombuffer(raw, np.float32).reshape(height, width, 4)
        else:
            pixels = np.frombuffer(raw, np.uint8).reshape(height, width, 4) / np.float32(255)
        # readPixels gives the bottom row first (GL's window coordinates)
        images.append(np.ascontiguousarray(pixels[::-1, :, :3], dtype=np.float32))
    return images


# --- a whole project in wgpu-shadertoy ------------------------------------------------------


def render_wgpu_project(
    project: Project, width: int, height: int, time: float, frames: int, timeout: float = 120.0
) -> np.ndarray:
    """The Image of a ShaderToy project's last frame in wgpu-shadertoy (its buffers and
    pictures bound as the project says), `frames` frames from iTime `time`, 1/60 s apart: float32
    H x W x 3 in [0, 1], row 0 at the top. Raises RunnerFailure where it cannot draw it."""
    with tempfile.TemporaryDirectory(prefix="glint-wgpu-project-") as folder:
        passes = []
        for index, item in enumerate(project.passes):
            inputs = []
            for entry in item.inputs:
                if entry.kind == "silent":
                    continue  # black, as every unbound channel
                read = {
                    "channel": entry.channel, "kind": entry.kind, "buffer": entry.buffer,
                    "filter": entry.filter, "wrap": entry.wrap, "vflip": entry.vflip,
                }  # fmt: skip
                if entry.file is not None:
                    read["path"] = str(Path(folder) / f"picture-{index}-{entry.channel}.npy")
                    np.save(read["path"], np.asarray(Image.open(entry.file).convert("RGBA")))
                inputs.append(read)
            passes.append({"code": item.code, "buffer": item.buffer, "inputs": inputs})
        job = {"common": project.common, "passes": passes, "width": width, "height": height,
               "time": time, "frames": frames, "output": folder}  # fmt: skip
        return _run_child("wgpu-project", job, Path(folder), timeout)


def render_wgpu_json(
    path: Path, width: int, height: int, time: float, timeout: float = 120.0
) -> np.ndarray:
    """ShaderToy JSON as wgpu-shadertoy's own `Shadertoy.from_json` loads it, one frame at
    iTime `time`: float32 H x W x 3 in [0, 1], row 0 at the top."""
    with tempfile.TemporaryDirectory(prefix="glint-wgpu-json-") as folder:
        job = {"json": str(path), "width": width, "height": height, "time": time, "output": folder}
        return _run_child("wgpu-json", job, Path(folder), timeout)


def _run_child(mode: str, job: dict[str, Any], folder: Path, timeout: float) -> np.ndarray:
    """Run this module as `mode`'s child process on `job` (written to `folder`) and read back
    the image it saves there; RunnerFailure, with its log, where it saves none."""
    job_path = folder / "job.json"
    job_path.write_text(json.dumps(job))
    try:
        done = subprocess.run(
            [sys.executable, __file__, mode, str(job_path)],
            env=os.environ | WGPU_ENV, capture_output=True, timeout=timeout,
        )  # fmt: skip
    except subprocess.TimeoutExpired:
        raise RunnerFailure(f"wgpu-shadertoy took more than {timeout:g} s") from None
    image = folder / "image.npy"
    if done.returncode or not image.is_file():
        log = (done.stdout + done.stderr).decode(errors="replace")[-2000:]
        raise RunnerFailure(f"wgpu-shadertoy failed (exit {done.returncode}):\n{log}")
    return np.load(image)


def _wgpu_json_worker(job_path: str) -> int:
    job = json.loads(Path(job_path).read_text())
    from wgpu_shadertoy import Shadertoy

    shadertoy = Shadertoy.from_json(
        job["json"], resolution=(job["width"], job["height"]), offscreen=True, use_cache=False
    )
    frame = shadertoy.snapshot(
        time_float=job["time"], time_delta=TIME_DELTA, frame=0, framerate=60.0,
        mouse_pos=(0.0, 0.0, 0.0, 0.0), date=DATE,
    )  # fmt: skip
    np.save(Path(job["output"]) / "image.npy", _pixels(shadertoy, frame))
    return 0


def _wgpu_project_worker(job_path: str) -> int:
    job = json.loads(Path(job_path).read_text())
    from wgpu_shadertoy import Shadertoy
    from wgpu_shadertoy.inputs import ShadertoyChannelBuffer, ShadertoyChannelTexture
    from wgpu_shadertoy.passes import BufferRenderPass

    def channels(inputs: list[dict[str, Any]]) -> list[Any]:
        bound: list[Any] = [ShadertoyChannelTexture() for _ in range(4)]
        for entry in inputs:
            options = {"wrap": entry["wrap"], "filter": entry["filter"]}
            if entry["kind"] == "buffer":
                bound[entry["channel"]] = ShadertoyChannelBuffer(entry["buffer"], **options)
            else:
                data = np.load(entry["path"])
                bound[entry["channel"]] = ShadertoyChannelTexture(
                    data, vflip=entry["vflip"], **options
                )
        return bound

    buffers = [
        BufferRenderPass(
            buffer_idx=item["buffer"].lower(), code=item["code"], inputs=channels(item["inputs"])
        )  # fmt: skip
        for item in job["passes"]
        if item["buffer"]
    ]
    image = next(item for item in job["passes"] if not item["buffer"])
    shadertoy = Shadertoy(
        image["code"], common=job["common"], resolution=(job["width"], job["height"]),
        shader_type="glsl", offscreen=True, inputs=channels(image["inputs"]), buffers=buffers,
    )  # fmt: skip
    frame = None
    for number in range(job["frames"]):
        frame = shadertoy.snapshot(
            time_float=job["time"] + number * TIME_DELTA, time_delta=TIME_DELTA, frame=number,
            framerate=60.0, mouse_pos=(0.0, 0.0, 0.0, 0.0), date=DATE,
        )  # fmt: skip
    np.save(Path(job["output"]) / "image.npy", _pixels(shadertoy, frame))
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("wgpu", "wgpu-project", "wgpu-json"):
        sys.exit("usage: runners.py wgpu|wgpu-project|wgpu-json JOB.json")
    if sys.argv[1] == "wgpu-project":
        sys.exit(_wgpu_project_worker(sys.argv[2]))
    if sys.argv[1] == "wgpu-json":
        sys.exit(_wgpu_json_worker(sys.argv[2]))
    sys.exit(_wgpu_worker(sys.argv[2]))
