"""mkdocs hook: before each build, assemble the docs folder from site/docs and the pages glint
generates (glint.compiler.site.build_docs), and build from it.

The folder is build/site-docs, or $GLINT_SITE_DOCS (the tests build into a temporary folder).
Only changed files are rewritten, so `mkdocs serve` does not rebuild in a loop.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from glint.compiler.site import build_docs


def on_config(config: Any) -> Any:
    root = Path(config.config_file_path).resolve().parent
    source = Path(config.docs_dir)
    if not source.is_absolute():
        source = root / source
    target = Path(os.environ.get("GLINT_SITE_DOCS") or root / "build" / "site-docs")
    build_docs(source, target, readme=root / "README.md")
    config.docs_dir = str(target)
    return config
