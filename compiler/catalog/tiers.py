"""The tier table (snippets/tiers.toml): for each tier, the variant of each quality slot."""

from __future__ import annotations

import tomllib
from importlib import resources

TIERS = ("fast", "balanced", "reference")


def tier_table() -> dict[str, dict[str, str]]:
    """tier (and `rough_diffuse`) -> slot -> variant name, as tiers.toml writes it."""
    text = (resources.files("glint.snippets") / "tiers.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)
