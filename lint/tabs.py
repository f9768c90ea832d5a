"""The ShaderToy tab each linted file runs in: the Common tab that ShaderToy puts in front of a
pass's code, named by `--common FILE` or found beside the file as `NAME.common.glsl` (what
`glint compose --split common` writes), and the channels' types.

A file with a Common tab is analysed with that code in front; findings in the Common tab's code
are reported once, on the Common tab's own file, which is linted with the files that use it
(named or not): a Common tab that does not compile must not leave its Image tab "clean".
A file named `NAME.common.glsl` (or the `--common` file) is linted as a Common tab: alone,
with no mainImage, as ShaderToy compiles it.

A ShaderToy project (its JSON, or a folder of tabs with `image.glsl`) is linted pass by pass,
each with the project's Common tab in front and its channels typed by what they read; a
folder's findings at the tab's own file, a JSON's under `PROJECT:PASS`
(`shader.json:Buffer A:12:5`), the pass a logical location in SARIF."""

from __future__ import annotations

from pathlib import Path

from glint.compiler.errors import EnvironmentProblem, UsageError, printable
from glint.compiler.target.shadertoy import Tab, common_sibling, is_common_file
from glint.compiler.target.shadertoy_project import Project, is_project, read_project

from .options import Options
from .runner import decode


def plan(
    files: list[str], explicit: tuple[str, str] | None, options: Options
) -> list[tuple[str, Tab]]:
    """Each file to lint with its tab, in order: with the `explicit` Common tab (its name and
    text: `--common`), else with the one beside it. A Common tab that a file uses and that is
    not among the files comes just before the first such file."""
    seen = {_identity(file) for file in files}
    planned: list[tuple[str, Tab]] = []
    for file in files:
        if file != "-" and (is_common_file(file) or (explicit and _same(file, explicit[0]))):
            planned.append((file, Tab(channels=options.channels, is_common=True)))
            continue
        found = explicit if explicit is not None else sibling_common(file)
        if found is None:
            planned.append((file, options.tab()))
            continue
        name, text = found
        if _identity(name) not in seen:
            seen.add(_identity(name))
            planned.append((name, Tab(channels=options.channels, is_common=True)))
        planned.append((file, Tab(common=text, common_file=name, channels=options.channels)))
    return planned


def read_common(path: str, label: str = "--common") -> tuple[str, str]:
    """`--common FILE`: its name and text, or a usage error saying why it cannot be used."""
    where = Path(path)
    said = f"{label} {printable(path)}"
    if not where.is_file():
        what = "not a regular file" if where.exists() else "no such file"
        raise UsageError(f"{said}: {what}; name the Common tab's .glsl file")
    try:
        data = where.read_bytes()
    except OSError as exc:
        raise EnvironmentProblem(f"{said}: cannot read: {exc.strerror}") from None
    text, problem = decode(data, path)
    if problem:
        raise UsageError(f"{said}: {problem}")
    return path, text


def sibling_common(file: str) -> tuple[str, str] | None:
    """`NAME.common.glsl` beside `NAME.glsl`: its name and text, if it is there and is text
    (an unreadable one is reported when it is linted itself)."""
    if file == "-":
        return None
    path = common_sibling(file)
    if not path.is_file():
        return None
    try:
        text, problem = decode(path.read_bytes(), str(path))
    except OSError:
        return None
    return (str(path), text) if not problem else None


def _identity(file: str) -> str:
    return file if file == "-" else str(Path(file).resolve())


def _same(file: str, other: str) -> bool:
    return _identity(file) == _identity(other)


def split_projects(paths: list[str]) -> tuple[list[str], list[Project]]:
    """The paths that are ShaderToy projects (a `.json` file, a folder holding image.glsl),
    read, apart from the rest."""
    rest: list[str] = []
    projects: list[Project] = []
    for raw in paths:
        if is_project(raw):
            projects.append(read_project(raw, pictures=False))
        else:
            rest.append(raw)
    return rest, projects


def project_tabs(project: Project, options: Options) -> list[tuple[str, Tab, str]]:
    """Each pass of `project` as lint takes a file: the name its findings are reported under,
    its tab (the Common tab in front, its channels' types) and its code; the Common tab first,
    alone, as ShaderToy compiles it."""
    tabs: list[tuple[str, Tab, str]] = []
    # a folder's tab is reported at its own file; a JSON's pass as PROJECT:PASS
    common_name = project.common_file or f"{project.origin}:Common"
    if project.common:
        tabs.append((common_name, Tab(channels=options.channels, is_common=True), project.common))
    for item in project.passes:
        tab = Tab(common=project.common, common_file=common_name, channels=item.channel_kinds())
        tabs.append((item.file or f"{project.origin}:{item.name}", tab, item.code))
    return tabs
