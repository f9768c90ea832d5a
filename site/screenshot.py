"""The README's picture of the docs site: D.ggx's page of a built site, in headless Chromium.

    python site/screenshot.py build/site site/screenshot.png   (`make screenshot` runs it)

It serves the built site on 127.0.0.1, loads the page in Debian's `chromium` through Playwright
(the same browser as the browser tests), waits for KaTeX to typeset the formula and writes a
1200x800 PNG, reduced to a palette so that the committed file stays small.
"""

from __future__ import annotations

import argparse
import functools
import io
import shutil
import sys
import threading
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

PAGE = "catalog/D.ggx/"
SIZE = {"width": 1200, "height": 800}
CHROMIUM_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox"]
_TYPESET = """() => [...document.querySelectorAll(".arithmatex")].every(
  (e) => e.querySelector(".katex"))"""


class _Quiet(SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 (the base's name)
        pass


def screenshot(site: Path, out: Path, page_path: str = PAGE) -> None:
    """Serve `site`, load `page_path` and write its screenshot to `out`."""
    from PIL import Image
    from playwright.sync_api import sync_playwright

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("Debian's chromium is not installed: make screenshot installs it")
    handler = functools.partial(_Quiet, directory=str(site))
    server = ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=chromium, args=CHROMIUM_ARGS)
            page = browser.new_page(viewport=SIZE)
            page.goto(f"http://127.0.0.1:{server.server_address[1]}/{page_path}")
            page.wait_for_function(_TYPESET)
            page.wait_for_load_state("networkidle")  # the KaTeX fonts
            png = page.screenshot()
            browser.close()
    finally:
        server.shutdown()
        server.server_close()
    # a docs page is mostly flat colour: 256 colours keep it sharp at a fraction of the size
    image = Image.open(io.BytesIO(png)).convert("RGB").quantize(colors=256, dither=0)
    out.parent.mkdir(parents=True, exist_ok=True)
    image.save(out, optimize=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=Path, help="the built site (make site: build/site)")
    parser.add_argument("out", type=Path, help="the PNG to write")
    parser.add_argument("--page", default=PAGE, help=f"the page, under the site (default {PAGE})")
    args = parser.parse_args(argv)
    if not (args.site / args.page / "index.html").is_file():
        parser.error(f"{args.site / args.page} is not built: run make site first")
    screenshot(args.site, args.out, args.page)
    print(f"screenshot: {args.out} ({args.out.stat().st_size // 1024} KiB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
