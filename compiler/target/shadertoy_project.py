"""A ShaderToy project: its passes (Buffers A-D, then the Image), the Common tab ShaderToy puts
in front of each, and what each pass's channels read (a buffer, a picture file, a cubemap).

Read from ShaderToy's JSON (what its export and its API give: one `{"Shader": ...}` object, or
the API's list of them, the first taken) or from a folder of tabs (`common.glsl`,
`buffer_a.glsl` ... `buffer_d.glsl`, `image.glsl`, and `channels.toml` for what the channels
read). Every problem is one InputError naming the file, the pass and the key.

ShaderToy draws the buffers in the order A, B, C, D, then the Image, every frame. A pass that
reads a buffer sees what that buffer drew last: this frame's for a buffer drawn before it, the
previous frame's for itself and the buffers after it.
"""

from __future__ import annotations

import json
import re
import tomllib
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from glint.compiler.errors import InputError
from glint.compiler.files import MiB, read_user_text
from glint.compiler.target.shadertoy import CHANNELS, Tab, wrap_tab

BUFFERS = ("A", "B", "C", "D")
# The ids ShaderToy gives each buffer's output (and an input that reads it names), in both of
# the forms its JSON has used: the short string and the number.
BUFFER_IDS: dict[str, str] = {
    "4dXGR8": "A", "XsXGR8": "B", "4sXGR8": "C", "XdfGR8": "D",
    "257": "A", "258": "B", "259": "C", "260": "D",
}  # fmt: skip
# What a channel may read, and the sampler type it is declared as.
KINDS = {"buffer": "2d", "texture": "2d", "cubemap": "cube", "volume": "3d", "silent": "2d"}
# Inputs that a still render sees black, as ShaderToy does with no key pressed and no sound
# playing: bound to black rather than refused.
SILENT = ("keyboard", "music", "musicstream", "mic")
FILTERS = ("mipmap", "linear", "nearest")
WRAPS = ("repeat", "clamp")
PROJECT_FILE_LIMIT = 16 * MiB


@dataclass(frozen=True)
class ChannelInput:
    """What one channel of a pass reads."""

    channel: int  # 0 to 3
    kind: str  # a KINDS key
    buffer: str = ""  # "A" to "D" for a buffer
    file: Path | None = None  # the picture for a texture; a cubemap's first face (+x)
    faces: tuple[Path, ...] = ()  # a cubemap's six pictures: +x, -x, +y, -y, +z, -z
    filter: str = "mipmap"
    wrap: str = "repeat"
    vflip: bool = True  # a picture's bottom row at v = 0, as ShaderToy binds one by default


@dataclass(frozen=True)
class Pass:
    name: str  # "Buffer A" ... "Image"
    code: str
    inputs: tuple[ChannelInput, ...] = ()
    buffer: str = ""  # the buffer it draws into ("" for the Image)
    file: str = ""  # the tab's own file (a folder's), where it has one

    def channel_kinds(self) -> tuple[str, ...]:
        """The sampler kind of each channel ("2d", "cube", "3d"), 2D where nothing is bound."""
        kinds = ["2d"] * CHANNELS
        for item in self.inputs:
            kinds[item.channel] = KINDS[item.kind]
        return tuple(kinds)


@dataclass(frozen=True)
class Project:
    origin: str  # the file or folder it was read from, for messages
    passes: tuple[Pass, ...]  # the buffers in ShaderToy's order, then the Image
    common: str = ""
    common_file: str = ""  # the Common tab's own file (a folder's), where it has one

    def unbound_reads(self) -> list[tuple[str, int]]:
        """(pass, channel) for each channel a pass's code (or the Common tab it gets) reads
        with nothing bound to it: drawn, it would sample black."""
        common = _CHANNEL_READ.findall(_without_comments(self.common))
        found = []
        for item in self.passes:
            read = {int(n) for n in [*common, *_CHANNEL_READ.findall(_without_comments(item.code))]}
            bound = {entry.channel for entry in item.inputs}
            found += [(item.name, channel) for channel in sorted(read - bound)]
        return found

    def source(self, item: Pass) -> str:
        """The complete fragment shader of a pass: ShaderToy's prelude with its channels' types,
        the Common tab, the pass's code and a main that calls mainImage."""
        tab = Tab(common=self.common, common_file=self.origin, channels=item.channel_kinds())
        return wrap_tab("shadertoy", item.code, tab)[0]


_CHANNEL_READ = re.compile(r"\biChannel([0-3])\b")
_COMMENT = re.compile(r"//[^\n]*|/\*.*?(?:\*/|\Z)", re.S)


def _without_comments(code: str) -> str:
    return _COMMENT.sub(" ", code)


def is_project(path: str | Path) -> bool:
    """Whether a path given to a command is a ShaderToy project: a `.json` file, or a folder
    holding the Image tab of a folder of tabs."""
    path = Path(path)
    return (path.suffix == ".json" and path.is_file()) or (path / TAB_FILES["Image"]).is_file()


def read_project(path: str | Path, pictures: bool = True) -> Project:
    """A project from a ShaderToy JSON file or a folder of tabs. `pictures`: find each texture's
    file (a render needs them; lint, which needs only the channels' types, does not)."""
    path = Path(path)
    if path.is_dir():
        return _read_folder(path, pictures)
    if not path.exists():
        raise InputError(f"{path}: no such file or folder")
    text = read_user_text(path, PROJECT_FILE_LIMIT, "ShaderToy JSON file")
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}: not JSON ({exc}); expected ShaderToy's export") from None
    return project_from_json(data, path, pictures)


def project_from_json(data: Any, path: Path, pictures: bool = True) -> Project:
    """A project from ShaderToy's JSON: `{"Shader": {"renderpass": [...]}}`, or a list of them
    (the API's answer), the first taken. Pictures are looked for by the name ShaderToy gives
    them (`/media/a/NAME.png`), beside the JSON file or in `media/` there."""
    shader = _shader_object(data)
    passes = shader.get("renderpass") if isinstance(shader, dict) else None
    if not isinstance(passes, list) or not passes:
        raise InputError(
            f'{path}: not ShaderToy\'s JSON: expected {{"Shader": {{"renderpass": [...]}}}} '
            "(what ShaderToy's export and its API give) or the shader object itself"
        )
    common = ""
    found: dict[str, Pass] = {}
    # what each pass draws into, by its output's id: an input that reads a buffer names it
    outputs = {
        str(output.get("id")): _buffer_of(item, f"{path}: renderpass[{index}]")
        for index, item in enumerate(passes)
        if isinstance(item, dict) and item.get("type") == "buffer"
        for output in item.get("outputs", []) or []
        if isinstance(output, dict)
    }
    for index, item in enumerate(passes):
        where = f"{path}: renderpass[{index}]"
        if not isinstance(item, dict):
            raise InputError(f"{where}: a pass is an object, not {type(item).__name__}")
        kind = item.get("type")
        code = item.get("code")
        if not isinstance(code, str):
            raise InputError(f"{where}.code: missing, or not a string of GLSL")
        if kind == "common":
            common = code
            continue
        if kind == "sound":  # ShaderToy's audio: nothing of it reaches the picture
            continue
        if kind == "image":
            name, buffer = "Image", ""
        elif kind == "buffer":
            buffer = _buffer_of(item, where)
            name = f"Buffer {buffer}"
        else:
            raise InputError(
                f"{where}.type: {kind!r} passes are not drawn by glint (it draws image, buffer "
                "and common passes); remove the pass or render without it"
            )
        where = f"{path}: {name}"
        if name in found:
            raise InputError(f"{where}: the project has two such passes")
        inputs = item.get("inputs", [])
        if not isinstance(inputs, list):
            raise InputError(f"{where}.inputs: a list of channel inputs, not {inputs!r}")
        read = tuple(_json_input(entry, f"{where}.inputs[{i}]", path.parent, outputs, pictures)
                     for i, entry in enumerate(inputs))  # fmt: skip
        found[name] = Pass(name, code, _one_per_channel(read, where), buffer)
    return _ordered(found, common, str(path))


def _buffer_of(item: dict[str, Any], where: str) -> str:
    """Which buffer a buffer pass draws into: its output's id, else the last letter of its
    name ("Buffer B")."""
    for output in item.get("outputs", []) or []:
        if isinstance(output, dict) and str(output.get("id")) in BUFFER_IDS:
            return BUFFER_IDS[str(output["id"])]
    name = str(item.get("name", "")).strip()
    if name[-1:].upper() in BUFFERS:
        return name[-1].upper()
    raise InputError(f"{where}: a buffer pass with no output id or name that says which buffer")


def _shader_object(data: Any) -> Any:
    """The shader of ShaderToy's JSON in the forms it comes in: `{"Shader": {...}}` (the
    export), `{"Shader": [{...}]}` and a list of those (the API's), or the shader object
    itself; the first where there are several."""
    if isinstance(data, list) and data:
        data = data[0]
    if isinstance(data, dict) and "Shader" in data:
        data = data["Shader"]
    if isinstance(data, list) and data:
        data = data[0]
    return data


def _json_input(
    entry: Any,
    where: str,
    folder: Path,
    outputs: dict[str, str] | None = None,
    pictures: bool = True,
) -> ChannelInput:
    if not isinstance(entry, dict):
        raise InputError(f"{where}: an input is an object, not {type(entry).__name__}")
    channel = entry.get("channel")
    if not isinstance(channel, int) or isinstance(channel, bool) or not 0 <= channel < CHANNELS:
        raise InputError(f"{where}.channel: {channel!r} is not a channel (0 to 3)")
    kind = entry.get("ctype", entry.get("type"))
    sampler = entry.get("sampler") or {}
    options = {
        "filter": str(sampler.get("filter", "mipmap" if kind == "texture" else "linear")),
        "wrap": str(sampler.get("wrap", "repeat" if kind == "texture" else "clamp")),
        "vflip": str(sampler.get("vflip", "true")).lower() == "true",
    }
    _check_options(options, where)
    if kind == "buffer":
        buffer = {**BUFFER_IDS, **(outputs or {})}.get(str(entry.get("id")))
        if buffer is None:
            raise InputError(f"{where}.id: {entry.get('id')!r} is not one of ShaderToy's buffers")
        return ChannelInput(channel, "buffer", buffer=buffer, **options)
    if kind == "texture":
        found = _media(entry, where, folder) if pictures else None
        return ChannelInput(channel, "texture", file=found, **options)
    if kind in SILENT:  # a still render: no key pressed, no sound playing; black, as ShaderToy
        return ChannelInput(channel, "silent", **options)
    if kind == "cubemap":
        faces = _faces(_media(entry, where, folder)) if pictures else ()
        options["vflip"] = str(sampler.get("vflip", "false")).lower() == "true"
        return ChannelInput(channel, "cubemap", file=faces[0] if faces else None, faces=faces,
                            **options)  # fmt: skip
    if not pictures and kind in ("volume", "video", "webcam"):  # typed, for lint
        return ChannelInput(channel, "cubemap" if kind == "cubemap" else "volume"
                            if kind == "volume" else "texture", **options)  # fmt: skip
    raise InputError(
        f"{where}: a {kind!r} channel is not bound by glint yet (it binds buffers and "
        "textures); bind it in ShaderToy, or leave the channel out"
    )


def _media(entry: dict[str, Any], where: str, folder: Path) -> Path:
    """The local picture for a texture input: its file name beside the JSON file or in media/."""
    source = str(entry.get("src") or entry.get("filepath") or "")
    name = Path(source).name
    if not name:
        raise InputError(f"{where}.src: a texture input names no picture")
    for candidate in (folder / name, folder / "media" / name):
        if candidate.is_file():
            return candidate
    raise InputError(
        f"{where}.src: the picture {source} is not here; put {name} beside the JSON file or in "
        f"{folder / 'media'}"
    )


def _faces(first: Path) -> tuple[Path, ...]:
    """A cubemap's six faces as ShaderToy names them: NAME.png (+x), then NAME_1.png (-x) to
    NAME_5.png (-z) beside it."""
    faces = [first] + [first.with_name(f"{first.stem}_{i}{first.suffix}") for i in range(1, 6)]
    missing = [face.name for face in faces if not face.is_file()]
    if missing:
        raise InputError(
            f"{first}: a cubemap is six pictures, {first.name} (+x) and {faces[1].name} (-x) to "
            f"{faces[5].name} (-z) beside it; missing: {', '.join(missing)}"
        )
    return tuple(faces)


def _check_options(options: dict[str, Any], where: str) -> None:
    if options["filter"] not in FILTERS:
        raise InputError(f"{where}.sampler.filter: {options['filter']!r}; one of {FILTERS}")
    if options["wrap"] not in WRAPS:
        raise InputError(f"{where}.sampler.wrap: {options['wrap']!r}; one of {WRAPS}")


def _one_per_channel(inputs: tuple[ChannelInput, ...], where: str) -> tuple[ChannelInput, ...]:
    seen: set[int] = set()
    for item in inputs:
        if item.channel in seen:
            raise InputError(f"{where}: two inputs on iChannel{item.channel}")
        seen.add(item.channel)
    return inputs


def _ordered(found: dict[str, Pass], common: str, origin: str) -> Project:
    """The passes in ShaderToy's order; every buffer read is a buffer the project draws."""
    if "Image" not in found:
        raise InputError(f"{origin}: the project has no Image pass, which is what ShaderToy shows")
    order = [f"Buffer {b}" for b in BUFFERS if f"Buffer {b}" in found] + ["Image"]
    drawn = {found[name].buffer for name in order}
    for name in order:
        for item in found[name].inputs:
            if item.kind == "buffer" and item.buffer not in drawn:
                raise InputError(
                    f"{origin}: {name}: iChannel{item.channel} reads Buffer {item.buffer}, which "
                    "the project does not draw (it would read black)"
                )
    return Project(origin, tuple(found[name] for name in order), common)


# A folder of tabs: the file of each pass, and channels.toml for what the channels read.
TAB_FILES = {"Image": "image.glsl", **{f"Buffer {b}": f"buffer_{b.lower()}.glsl" for b in BUFFERS}}
CHANNELS_FILE = "channels.toml"


def _read_folder(folder: Path, pictures: bool = True) -> Project:
    """A folder of tabs. channels.toml has a table per pass (`[image]`, `[buffer_a]` ...), a
    key per channel: `0 = "buffer_a"` (a buffer), `1 = "stone.png"` (a picture, relative to
    the folder) or `1 = { file = "stone.png", filter = "linear", wrap = "clamp" }`."""
    tables: dict[str, Any] = {}
    listed = folder / CHANNELS_FILE
    if listed.is_file():
        text = read_user_text(listed, PROJECT_FILE_LIMIT, "channels file")
        try:
            tables = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"{listed}: not valid TOML: {exc}") from None
    found: dict[str, Pass] = {}
    for name, file in TAB_FILES.items():
        tab = folder / file
        if not tab.is_file():
            continue
        code = read_user_text(tab, PROJECT_FILE_LIMIT, "GLSL tab")
        key = Path(file).stem
        table = tables.pop(key, {})
        where = f"{listed}: [{key}]"
        if not isinstance(table, dict):
            raise InputError(f'{where}: a table of channels, e.g. 0 = "buffer_a"')
        inputs = tuple(
            _folder_input(k, v, f"{where} {k}", folder, pictures) for k, v in table.items()
        )
        buffer = name[-1] if name.startswith("Buffer") else ""
        found[name] = Pass(name, code, _one_per_channel(inputs, where), buffer, str(tab))
    if tables:
        unknown = ", ".join(sorted(tables))
        raise InputError(
            f"{listed}: [{unknown}] is not a pass of the folder (the passes: "
            f"{', '.join(Path(f).stem for n, f in TAB_FILES.items() if n in found)})"
        )
    common_file = folder / "common.glsl"
    common = ""
    if common_file.is_file():
        common = read_user_text(common_file, PROJECT_FILE_LIMIT, "GLSL tab")
    if not found:
        raise InputError(
            f"{folder}: no tab here; a project folder holds image.glsl, and buffer_a.glsl ... "
            "buffer_d.glsl and common.glsl as it needs"
        )
    project = _ordered(found, common, str(folder))
    return replace(project, common_file=str(common_file) if common else "")


def _folder_input(
    key: str, value: Any, where: str, folder: Path, pictures: bool = True
) -> ChannelInput:
    if key not in {str(i) for i in range(CHANNELS)}:
        raise InputError(f"{where}: {key!r} is not a channel (0 to 3)")
    channel = int(key)
    if isinstance(value, str):
        value = {"file": value}
    if not isinstance(value, dict):
        raise InputError(f"{where}: a buffer name, a picture file, or a table with `file`")
    source = str(value.get("file", ""))
    if source.lower() in {f"buffer_{b.lower()}" for b in BUFFERS}:
        options = {"filter": "linear", "wrap": "clamp", "vflip": True}
        options |= {k: value[k] for k in ("filter", "wrap", "vflip") if k in value}
        _check_options(options, where)
        return ChannelInput(channel, "buffer", buffer=source[-1].upper(), **options)
    picture = folder / source
    if pictures and not picture.is_file():
        raise InputError(f"{where}: {source!r}: no such picture in {folder}")
    cube = value.get("type") == "cubemap"
    options = {"filter": "mipmap", "wrap": "repeat", "vflip": not cube}
    options |= {k: value[k] for k in ("filter", "wrap", "vflip") if k in value}
    _check_options(options, where)
    if cube:
        faces = _faces(picture) if pictures else ()
        return ChannelInput(channel, "cubemap", file=picture, faces=faces, **options)
    return ChannelInput(channel, "texture", file=picture, **options)


# The output id ShaderToy gives the Image pass, and each buffer's (the reverse of BUFFER_IDS).
IMAGE_OUTPUT = "4dfGRr"
BUFFER_OUTPUTS = {"A": "4dXGR8", "B": "XsXGR8", "C": "4sXGR8", "D": "XdfGR8"}


def project_json(project: Project, name: str, description: str = "") -> dict[str, Any]:
    """The project as ShaderToy's JSON (the export's form), which ShaderToy's import, glint and
    wgpu-shadertoy's `Shadertoy.from_json` read. A picture is named by its file's name: put the
    file beside the JSON (ShaderToy itself binds only its own pictures)."""
    passes: list[dict[str, Any]] = []
    if project.common:
        passes.append(_pass_json("Common", "common", project.common, [], []))
    for item in project.passes:
        inputs = [_input_json(entry) for entry in item.inputs]
        output = BUFFER_OUTPUTS[item.buffer] if item.buffer else IMAGE_OUTPUT
        kind = "buffer" if item.buffer else "image"
        passes.append(
            _pass_json(item.name, kind, item.code, inputs, [{"id": output, "channel": 0}])
        )
    info = {"id": "", "name": name, "username": "glint", "description": description,
            "tags": ["glint"]}  # fmt: skip
    return {"Shader": {"ver": "0.1", "info": info, "renderpass": passes}}


def _pass_json(
    name: str, kind: str, code: str, inputs: list[dict[str, Any]], outputs: list[dict[str, Any]]
) -> dict[str, Any]:
    return {"inputs": inputs, "outputs": outputs, "code": code, "name": name,
            "description": "", "type": kind}  # fmt: skip


def _input_json(entry: ChannelInput) -> dict[str, Any]:
    sampler = {
        "filter": entry.filter,
        "wrap": entry.wrap,
        "vflip": "true" if entry.vflip else "false",
        "srgb": "false",
        "internal": "byte",
    }
    if entry.kind == "buffer":
        return {"id": BUFFER_OUTPUTS[entry.buffer], "type": "buffer", "channel": entry.channel,
                "sampler": sampler, "published": 1}  # fmt: skip
    if entry.kind not in ("texture", "cubemap") or entry.file is None:
        return {"id": entry.kind, "type": "keyboard" if entry.kind == "silent" else entry.kind,
                "channel": entry.channel, "sampler": sampler, "published": 1}  # fmt: skip
    # a picture by its file's name (a cubemap by its first face's: the others follow it)
    return {"id": entry.file.stem, "src": entry.file.name, "type": entry.kind,
            "channel": entry.channel, "sampler": sampler, "published": 1}  # fmt: skip
