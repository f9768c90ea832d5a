"""Per example scene and tier: frame time and FLIP against the reference tier; the seed's
template (`template.glsl`) as the baseline."""

from __future__ import annotations

from importlib import resources

TEMPLATE = "template.glsl"


def template_source() -> str:
    """The seed template as one monolithic ShaderToy shader (it renders the default scene)."""
    return (resources.files("glint.compiler.bench") / TEMPLATE).read_text(encoding="utf-8")
