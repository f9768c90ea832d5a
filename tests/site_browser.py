"""What the browser tests of the docs site share: building the site, serving it on 127.0.0.1 and
driving Debian's Chromium through Playwright. tests/conftest.py turns these into fixtures
(`built_site`, `site_url`, `browser`, `browser_page`); a test module marked `browser` uses them.

The browser is Debian's `chromium` package, never one downloaded by `playwright install` (CI has
no network for that); `make test` installs it, with the real KaTeX (libjs-katex fonts-katex)
the formulas are typeset with. SwiftShader gives a headless WebGL2.
"""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

if TYPE_CHECKING:
    from playwright.sync_api import Browser, Page

ROOT = Path(__file__).parent.parent
KATEX_DIR = Path("/usr/share/javascript/katex")  # Debian's libjs-katex (its fonts: fonts-katex)
CHROMIUM_NAMES = ("chromium", "chromium-browser")
CHROMIUM_ARGS = (
    "--use-angle=swiftshader",  # WebGL2 without a GPU or a display
    "--enable-unsafe-swiftshader",  # recent Chromium refuses SwiftShader WebGL without it
    "--no-sandbox",  # the tests may run as root (CI, containers)
)
MAKE_TEST = "run `make test`, which installs it"
# A few pictures only: each is a render on llvmpipe; the rest of the variants say they have none.
PICTURES = ("D.ggx", "F.schlick", "attenuation.quadratic")


@dataclass(frozen=True)
class BuiltSite:
    """A site built by `mkdocs build --strict` with the mkdocs hook, as `make site` builds it."""

    root: Path  # the HTML, what the server serves
    docs: Path  # the assembled docs folder (Markdown, pictures, KaTeX)
    pictures: tuple[str, ...]  # the ids whose pictures were rendered

    def pages(self) -> list[Path]:
        """Every HTML page, relative to the root (404.html included)."""
        return sorted(path.relative_to(self.root) for path in self.root.rglob("*.html"))


def chromium_path() -> str | None:
    found = (shutil.which(name) for name in CHROMIUM_NAMES)
    return next((path for path in found if path), None)


def build_site(tmp: Path, pictures: tuple[str, ...] = PICTURES) -> BuiltSite:
    """Build the site into `tmp` with the environment tests/test_site.py uses, but with the
    real KaTeX: here the formulas must typeset."""
    pytest.importorskip("mkdocs", reason=f"mkdocs is not installed: {MAKE_TEST}")
    pytest.importorskip("material", reason=f"mkdocs-material is not installed: {MAKE_TEST}")
    if not (KATEX_DIR / "katex.min.js").is_file():
        pytest.skip(f"KaTeX (libjs-katex, fonts-katex) is not installed: {MAKE_TEST}")
    env = os.environ | {
        "GLINT_SITE_DOCS": str(tmp / "docs"),
        "GLINT_KATEX_DIR": str(KATEX_DIR),
        "GLINT_SITE_CACHE": str(tmp / "cache"),
        "GLINT_SITE_PICTURES": ",".join(pictures),
    }
    command = [sys.executable, "-m", "mkdocs", "build", "--strict", "-q"]
    command += ["-f", str(ROOT / "mkdocs.yml"), "-d", str(tmp / "site")]
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=180)
    assert result.returncode == 0, result.stderr
    rendered = tuple(
        snippet_id
        for snippet_id in pictures
        if (tmp / "docs" / "img" / "variants" / f"{snippet_id}.png").is_file()
    )
    return BuiltSite(tmp / "site", tmp / "docs", rendered)


class _QuietHandler(SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 (the base's name)
        pass  # pytest shows a failing test's output; a line per request would drown it


class _Server(ThreadingHTTPServer):
    def handle_error(self, request: Any, client_address: Any) -> None:
        # the browser drops a connection when it navigates away mid-load: not the site's fault
        if not isinstance(sys.exc_info()[1], ConnectionError):
            super().handle_error(request, client_address)


@contextmanager
def serve(root: Path) -> Iterator[str]:
    """Serve `root` on 127.0.0.1 (a free port) in a thread; yields the base URL, ending in /."""
    handler = functools.partial(_QuietHandler, directory=str(root))
    server = _Server(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


@contextmanager
def launch_chromium() -> Iterator[Browser]:
    """Debian's Chromium, headless, driven by Playwright; skips where either is missing."""
    sync_api = pytest.importorskip(
        "playwright.sync_api", reason=f"playwright is not installed: {MAKE_TEST}"
    )
    executable = chromium_path()
    if executable is None:
        pytest.skip(f"Debian's chromium is not installed: {MAKE_TEST}")
    with sync_api.sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=executable, args=list(CHROMIUM_ARGS), headless=True
        )
        try:
            yield browser
        finally:
            browser.close()


@dataclass
class PageLog:
    """What a page did while the test watched it: console errors, uncaught exceptions, every
    request's URL, the responses that failed and the requests that got none."""

    console_errors: list[str] = field(default_factory=list)
    page_errors: list[str] = field(default_factory=list)
    requests: list[str] = field(default_factory=list)
    bad_responses: list[str] = field(default_factory=list)
    failed_requests: list[str] = field(default_factory=list)

    def problems(self) -> list[str]:
        """Everything that is wrong, one line each; empty when the page is clean."""
        return [
            *(f"console error: {text}" for text in self.console_errors),
            *(f"page error: {text}" for text in self.page_errors),
            *(f"bad response: {text}" for text in self.bad_responses),
            *(f"request failed: {text}" for text in self.failed_requests),
        ]


def watch(page: Page) -> PageLog:
    """Record what `page` does from now on."""
    log = PageLog()
    page.on(
        "console",
        lambda message: (
            log.console_errors.append(f"{message.text} ({page.url})")
            if message.type == "error"
            else None
        ),
    )
    page.on("pageerror", lambda error: log.page_errors.append(f"{error} ({page.url})"))
    page.on("request", lambda request: log.requests.append(request.url))
    page.on(
        "response",
        lambda response: (
            log.bad_responses.append(f"{response.status} {response.url}")
            if response.status >= 400
            else None
        ),
    )
    page.on(
        "requestfailed",
        lambda request: (
            # ERR_ABORTED: cancelled by the next navigation (the search worker, the favicon)
            log.failed_requests.append(f"{request.url}: {request.failure}")
            if "ERR_ABORTED" not in (request.failure or "")
            else None
        ),
    )
    return log
