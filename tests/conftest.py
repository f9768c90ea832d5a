"""Fixtures for the browser tests of the docs site (tests/site_browser.py does the work). They
are built lazily: a run that selects no browser test builds and launches nothing."""

from __future__ import annotations

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
