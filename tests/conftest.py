"""Fixtures for the browser tests of the docs site (tests/site_browser.py does the work). They
are built lazily: a run that selects no browser test builds and launches nothing."""

from __future__ import annotations

import os
import stat
from collections.abc import Iterator
from typing import TYPE_CHECKING

import pytest
from site_browser import BuiltSite, PageLog, build_site, launch_chromium, serve, watch

if TYPE_CHECKING:
    from playwright.sync_api import Browser, Page


@pytest.fixture(scope="session")
def built_site(tmp_path_factory: pytest.TempPathFactory) -> BuiltSite:
    """The docs site, built once per session (a few pictures, the real KaTeX)."""
    return build_site(tmp_path_factory.mktemp("browser-site"))


@pytest.fixture(scope="session")
def site_url(built_site: BuiltSite) -> Iterator[str]:
    """The built site served on 127.0.0.1: its base URL, ending in /."""
    with serve(built_site.root) as url:
        yield url


@pytest.fixture(scope="session")
def browser() -> Iterator[Browser]:
    """Debian's Chromium, headless, with WebGL2 through SwiftShader."""
    with launch_chromium() as launched:
        yield launched


@pytest.fixture
def browser_page(browser: Browser) -> Iterator[tuple[Page, PageLog]]:
    """A fresh page (its own context: no cache or storage shared between tests) and the log of
    what it does."""
    context = browser.new_context(viewport={"width": 1200, "height": 800})
    page = context.new_page()
    try:
        yield page, watch(page)
    finally:
        context.close()


@pytest.fixture
def null_device() -> Iterator[str]:
    """os.devnull, for a test that writes to it. Should the code under test rename a file over
    the device (the bug such a test looks for), the device is made again (as root: the whole
    machine needs it) and the test fails."""
    yield os.devnull
    if stat.S_ISCHR(os.stat(os.devnull).st_mode):
        return
    if os.geteuid() == 0:
        spare = os.path.join(os.path.dirname(os.devnull), ".null-glint-test")
        os.mknod(spare, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        os.chmod(spare, 0o666)  # mknod's mode went through the umask
        os.replace(spare, os.devnull)
    pytest.fail(f"{os.devnull} was replaced by a regular file (made again: {os.geteuid() == 0})")
