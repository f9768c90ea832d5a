"""The renderer: exact float output, ShaderToy's uniforms and orientation, and its watchdog."""

from __future__ import annotations

import time

import numpy as np
import pytest

from glint.compiler.errors import EnvironmentProblem, InputError, UsageError
from glint.compiler.render import image_stats, limits, render, render_full

pytestmark = pytest.mark.render

W, H = 64, 36


def shader(body: str) -> str:
    return f"void mainImage(out vec4 fragColor, in vec2 fragCoord) {{\n    {body}\n}}\n"


def test_constant_colour_is_exact_in_a_float_framebuffer() -> None:
    result = render_full(shader("fragColor = vec4(0.25, 2.5, -1.5, 0.75);"), W, H)
    assert result.image.shape == (H, W, 4) and result.image.dtype == np.float32
    assert (result.image == np.array([0.25, 2.5, -1.5, 0.75], dtype=np.float32)).all()
    assert result.glsl_version in ("300 es", "330")
    assert result.draw_seconds >= 0.0


def test_repeated_draws_are_each_timed_and_give_the_same_frame() -> None:
    once = render_full(shader("fragColor = vec4(fragCoord, iTime, 1.0);"), W, H, time=2.0)
    many = render_full(
        shader("fragColor = vec4(fragCoord, iTime, 1.0);"), W, H, time=2.0, repeats=4
    )
    assert len(once.draw_times) == 1 and len(many.draw_times) == 4
    assert all(t > 0.0 for t in many.draw_times)
    assert np.array_equal(once.image, many.image)


def test_rows_start_at_the_top_of_the_picture() -> None:
    img = render(shader("fragColor = vec4(fragCoord / iResolution.xy, 0.0, 1.0);"), W, H)
    # fragCoord is at pixel centres, so the bottom row has y = 0.5 / H.
    assert img[-1, 0, 1] == pytest.approx(0.5 / H)
    assert img[0, 0, 1] == pytest.approx(1 - 0.5 / H)
    assert (np.diff(img[:, 0, 1]) < 0).all()  # decreasing down the image
    assert img[0, 0, 0] == pytest.approx(0.5 / W) and img[0, -1, 0] == pytest.approx(1 - 0.5 / W)


def test_uniforms_arrive() -> None:
    body = (
        "fragColor = vec4(iTime, float(iFrame), iMouse.x + iMouse.w * 1000.0, "
        "iResolution.x + iResolution.z * 1000.0);"
    )
    img = render(shader(body), W, H, time=2.5, frame=7, mouse=(3.0, 4.0, 5.0, 6.0))
    np.testing.assert_array_equal(img[0, 0], [2.5, 7.0, 6003.0, W + 1000.0])


def test_secondary_uniforms_have_shadertoy_values() -> None:
    body = (
        "fragColor = vec4(iTimeDelta * iFrameRate, iSampleRate, iDate.x + iDate.z, "
        "iChannelTime[2] + iChannelResolution[1].z) + texture(iChannel3, fragCoord);"
    )
    img = render(shader(body), 8, 4, time=1.5, date=(2030.0, 5.0, 9.0, 10.0))
    np.testing.assert_allclose(img[2, 3], [1.0, 44100.0, 2039.0, 2.5], rtol=1e-6)


def test_nan_is_reported_by_image_stats() -> None:
    # Depends on a uniform, so the compiler cannot fold it away.
    img = render(shader("fragColor = vec4(sqrt(-1.0 - iTime), 0.0, 0.0, 1.0);"), 16, 8)
    stats = image_stats(img)
    assert stats["nan"] == 16 * 8
    assert stats["inf"] == 0


def test_non_terminating_shader_is_stopped() -> None:
    # llvmpipe cuts every loop off after 65535 iterations, so an endless loop alone would
    # finish; a heavy body (256 sines per iteration) keeps it busy for minutes.
    source = "#define X4(s) s s s s\n" + shader(
        "float a = fragCoord.x;\n"
        "    while (iTime >= 0.0) { X4(X4(X4(X4(a = sin(a) + 1.0;)))) }\n"
        "    fragColor = vec4(a);"
    )
    start = time.monotonic()
    with pytest.raises(InputError, match="did not finish within 5 s") as raised:
        render(source, W, H, timeout=5)
    assert time.monotonic() - start < 10
    assert raised.value.exit_code == 1


def test_compile_error_carries_the_driver_log_at_user_lines() -> None:
    source = shader("vec3 c = vec3(1.0);\n    fragColor = vec4(c, undefinedName);")
    with pytest.raises(InputError, match="rejected the shader") as raised:
        render(source, 8, 4)
    assert "undefinedName" in raised.value.message
    assert "3:" in raised.value.message  # line 3 of the user's code, not of the prelude


def test_missing_main_image_is_an_input_error() -> None:
    with pytest.raises(InputError, match="mainImage"):
        render("float helper() { return 1.0; }\n", 8, 4)


def test_bad_size_is_a_usage_error() -> None:
    with pytest.raises(UsageError):
        render(shader("fragColor = vec4(1.0);"), 0, 4)


def test_no_egl_driver_is_an_environment_problem(monkeypatch: pytest.MonkeyPatch) -> None:
    # An empty list of EGL vendors is what a machine without Mesa's EGL looks like to libglvnd.
    monkeypatch.setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json")
    with pytest.raises(EnvironmentProblem, match="libegl-mesa0") as raised:
        render(shader("fragColor = vec4(1.0);"), 8, 4)
    assert raised.value.exit_code == 2


def test_the_worker_runs_under_a_memory_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    """The worker's RLIMIT_DATA holds: a frame past it is "ran out of memory" with the size and
    the limit, while a small frame renders under the same limit. Two llvmpipe threads, so that
    the driver's own need (about 160 MB, measured) does not depend on this machine's CPUs."""
    monkeypatch.setenv("LP_NUM_THREADS", "2")
    monkeypatch.setattr(limits, "worker_memory_limit", lambda pixels, extra=0: 400 << 20)
    flat = shader("fragColor = vec4(0.5);")
    assert (render(flat, 64, 64) == 0.5).all()
    start = time.monotonic()
    with pytest.raises(InputError) as raised:
        render(flat, 8192, 4096)  # 512 MB for the frame alone
    message = raised.value.message
    assert message.startswith(
        "the renderer ran out of memory drawing a 8192x4096 image (its limit was 400 MB"
    ), message
    assert "render a smaller size, or simplify the shader" in message
    assert time.monotonic() - start < 30


def test_the_memory_limit_leaves_room_for_the_default_scene() -> None:
    """The limit for a 640x360 frame is well above what the default scene needs (159 MB of
    data with two threads, measured; 16 MB more for each further thread)."""
    threads = limits._llvmpipe_threads()
    needed = (159 << 20) + (16 << 20) * max(0, threads - 2)
    assert limits.worker_memory_limit(640 * 360) >= 2 * needed


def test_a_size_past_the_memory_available_is_refused_up_front(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(limits, "available_memory", lambda: 300 << 20)
    with pytest.raises(UsageError) as raised:
        render(shader("fragColor = vec4(1.0);"), 4096, 4096)
    assert raised.value.message.startswith("image size: 4096x4096 needs about ")
    assert "only 300 MB is available here; choose a smaller size" in raised.value.message


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"timeout": 0}, "timeout: must be more than 0"),
        ({"timeout": float("inf")}, "timeout: must be more than 0 and at most 3600 seconds"),
        ({"time": float("nan")}, "time: must be a finite number"),
        ({"frame": 2**31}, "frame: must be from 0 to 2147483647"),
        ({"mouse": (0.0, 0.0, float("inf"), 0.0)}, r"mouse\[2\]: must be a finite number"),
    ],
)
def test_values_the_renderer_cannot_take_are_usage_errors(
    kwargs: dict[str, object], message: str
) -> None:
    with pytest.raises(UsageError, match=message):
        render(shader("fragColor = vec4(1.0);"), 8, 4, **kwargs)  # type: ignore[arg-type]
