"""The tier table (snippets/tiers.toml): for each tier, the variant of each quality slot."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from importlib import resources

TIERS = ("fast", "balanced", "reference")


def tier_choice(tiers: Mapping[str, Mapping[str, str]], tier: str, slot: str) -> str | None:
    """The variant name `tier` takes for `slot`: tiers.toml lists for fast and reference only
    what differs from balanced, so balanced's where the tier names none (as the planner does)."""
    return tiers.get(tier, {}).get(slot) or tiers.get("balanced", {}).get(slot)


def tier_table() -> dict[str, dict[str, str]]:
    """tier (and `rough_diffuse`) -> slot -> variant name, as tiers.toml writes it."""
    text = (resources.files("glint.snippets") / "tiers.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)
