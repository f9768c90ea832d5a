"""The catalog index in a real browser: catalog-cards.js turns the table into one card per
variant, with its picture, and the slot selector and the text box filter them."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest
from site_browser import BuiltSite, PageLog

import glint

if TYPE_CHECKING:
    from playwright.sync_api import Page

pytestmark = pytest.mark.browser


def test_catalog_cards_and_filters(
    built_site: BuiltSite, site_url: str, browser_page: tuple[Page, PageLog]
) -> None:
    page, log = browser_page
    page.goto(f"{site_url}catalog/")
    page.wait_for_selector(".glint-card")
    cards = page.locator(".glint-card")
    catalog = glint.catalog()
    assert cards.count() == len(catalog)
    assert not page.locator("article table").first.is_visible()  # the cards replace it
    visible = page.locator(".glint-card:not([hidden])")
    pictured = page.locator(".glint-card img")
    assert pictured.count() == len(built_site.pictures)

    page.select_option(".glint-filter select", "D")
    in_slot = sum(1 for snippet in catalog.values() if snippet.slot == "D")
    assert visible.count() == in_slot
    assert f"{in_slot} of {len(catalog)}" in page.locator(".glint-count").inner_text()

    page.fill(".glint-filter input", "beckmann")
    matching = sorted(
        snippet_id
        for snippet_id, snippet in catalog.items()
        if snippet.slot == "D" and "beckmann" in f"{snippet_id} {snippet.summary}".lower()
    )
    assert "D.beckmann" in matching and len(matching) < in_slot
    shown = sorted(visible.nth(i).locator("a").first.inner_text() for i in range(visible.count()))
    assert shown == matching
    page.fill(".glint-filter input", "no such variant at all")
    assert visible.count() == 0
    page.select_option(".glint-filter select", "")
    page.fill(".glint-filter input", "")
    assert visible.count() == len(catalog)
    assert not log.problems()
