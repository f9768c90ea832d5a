"""glint's own script and stylesheet for the site (the catalog's cards and filter, long
formulas), copied from this package into `assets/`; mkdocs.yml loads them on every page."""

from __future__ import annotations

from importlib import resources
from pathlib import PurePosixPath

ASSETS = PurePosixPath("assets")
FILES = ("catalog-cards.js", "glint.css")


def site_assets() -> dict[PurePosixPath, bytes]:
    package = resources.files("glint.compiler.site")
    return {ASSETS / name: (package / name).read_bytes() for name in FILES}
