"""The pictures a scene binds to ShaderToy's channels ([channels], a material's albedo_texture),
for the site's live canvases: each picture a file of the site, and a manifest after the live
shader naming them by channel, which live-canvas.js reads to bind them as ShaderToy binds a
picture. Without them a canvas would sample black where glint's own render shows the picture.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import PurePosixPath

import glint

PICTURES_DIR = PurePosixPath("img") / "live" / "pictures"


def live_shader(shader: glint.Shader) -> tuple[str, dict[PurePosixPath, bytes]]:
    """The live canvas's shader of `shader` (webgl2, parameters as uniforms) with its channels'
    manifest, and the picture files it names (by content, so that scenes share a picture)."""
    text = shader.retarget("webgl2", params_as_uniforms=True).text
    scene = shader.scene
    files: dict[PurePosixPath, bytes] = {}
    channels: dict[str, str] = {}
    for unit, path in sorted(scene.picture_files().items()):
        data = path.read_bytes()
        name = PICTURES_DIR / f"{hashlib.sha256(data).hexdigest()[:16]}{path.suffix.lower()}"
        files[name] = data
        channels[str(unit)] = name.as_posix()
    if channels:
        text += f"/* glint-channels\n{json.dumps(channels)}\n*/\n"
    return text, files
