"""glint's documentation site: the pages generated from glint itself (the catalog, the command
line, Getting started) and the folder mkdocs builds from.

Generation is independent of the theme: `build_docs` writes Markdown files and static assets
into a docs folder, and the mkdocs hook `site/hooks.py` calls it before each build
(`make site`, `make serve`). This package is the top layer: it documents everything below it,
the linter's rules included.
"""

from __future__ import annotations

from .docs_tree import build_docs

__all__ = ["build_docs"]
