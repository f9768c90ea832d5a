"""KaTeX for the site, served from the site itself: the Debian packages `libjs-katex` and
`fonts-katex` install it (`make site` does), and it is copied under `assets/katex/`, so the
pages typeset their formulas with no network at all."""

from __future__ import annotations

from importlib import resources
from pathlib import Path, PurePosixPath

from glint.compiler.errors import EnvironmentProblem

KATEX_DIR = Path("/usr/share/javascript/katex")  # libjs-katex; its fonts/ is fonts-katex
ASSETS = PurePosixPath("assets/katex")
_FONT_SUFFIXES = (".woff2", ".woff", ".ttf")


def katex_files(katex_dir: Path = KATEX_DIR) -> dict[PurePosixPath, bytes]:
    """The KaTeX files the pages load, by their path under the docs folder."""
    wanted = ["katex.min.js", "katex.min.css", "contrib/auto-render.js"]
    missing = [name for name in wanted if not (katex_dir / name).is_file()]
    fonts = sorted(
        path for path in (katex_dir / "fonts").glob("KaTeX_*") if path.suffix in _FONT_SUFFIXES
    )
    if missing or not fonts:
        raise EnvironmentProblem(
            f"KaTeX is not in {katex_dir} ({', '.join(missing) or 'no fonts'} missing): install "
            "the Debian packages libjs-katex fonts-katex (make site does)"
        )
    files = {ASSETS / name: (katex_dir / name).read_bytes() for name in wanted}
    files |= {ASSETS / "fonts" / font.name: font.read_bytes() for font in fonts}
    init = resources.files("glint.compiler.site") / "katex-init.js"
    files[ASSETS / "katex-init.js"] = init.read_bytes()
    return files
