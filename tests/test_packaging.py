"""The distribution holds every package of the source tree: setuptools installs only the
packages pyproject.toml lists, so a new sub-package left out would work in this checkout (an
editable install finds it on disk) and be missing from a wheel."""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).parent.parent


def test_every_package_folder_is_in_the_distribution() -> None:
    setuptools = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    listed = set(setuptools["packages"])
    folders = {name: ROOT / path for name, path in setuptools["package-dir"].items()}
    found = set()
    for name, folder in folders.items():
        for init in folder.rglob("__init__.py"):
            parts = init.parent.relative_to(folder).parts
            if name == "glint.compiler" and parts[:1] == ("api",):
                continue  # the package `glint` itself (package-dir maps it)
            found.add(".".join((name, *parts)))
    assert found - listed == set(), "add these to [tool.setuptools] packages"
    assert listed - found == set(), "pyproject lists packages that do not exist"
