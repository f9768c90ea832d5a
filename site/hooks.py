"""mkdocs hook: before each build, assemble the docs folder from site/docs and the pages glint
generates (glint.compiler.site.build_docs), and build from it.

The folder is build/site-docs, or $GLINT_SITE_DOCS (the tests build into a temporary folder);
KaTeX comes from Debian's libjs-katex, or from $GLINT_KATEX_DIR (the tests give a stand-in where
the package is not installed, as in CI, which installs only what `make test` needs).
Only changed files are rewritten, so `mkdocs serve` does not rebuild in a loop.
Variant pictures are cached in build/site-cache, or $GLINT_SITE_CACHE; $GLINT_SITE_PICTURES
limits them ("none", or comma-separated snippet ids; the tests render only a few).
The variant pages' code editor is build/editor/glint-editor.js (`make editor`), or
$GLINT_EDITOR_BUNDLE; without it the code is shown read-only.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from glint.compiler.site import build_docs
from glint.compiler.site.katex_assets import KATEX_DIR
from glint.compiler.site.pictures import selection_from_env


def on_config(config: Any) -> Any:
    root = Path(config.config_file_path).resolve().parent
    source = Path(config.docs_dir)
    if not source.is_absolute():
        source = root / source
    target = Path(os.environ.get("GLINT_SITE_DOCS") or root / "build" / "site-docs")
    katex = Path(os.environ.get("GLINT_KATEX_DIR") or KATEX_DIR)
    cache = Path(os.environ.get("GLINT_SITE_CACHE") or root / "build" / "site-cache")
    pictures = selection_from_env(os.environ.get("GLINT_SITE_PICTURES"))
    bundle = root / "build" / "editor" / "glint-editor.js"
    editor = Path(os.environ.get("GLINT_EDITOR_BUNDLE") or bundle)
    build_docs(
        source,
        target,
        readme=root / "README.md",
        katex_dir=katex,
        picture_cache=cache,
        pictures=pictures,
        editor_bundle=editor,
    )
    config.docs_dir = str(target)
    return config
