"""A composed ShaderToy shader in two tabs: the lighting library for the Common tab, and a short
Image tab that uses it, so that glint's code drops into an existing multipass shader.

ShaderToy puts the Common tab before every pass's own code, ahead of the uniforms it declares
for that pass: code in Common cannot read iTime, iResolution or iMouse. So a unit that reads a
uniform (the camera, say) stays in the Image tab, with every unit that needs it (mainImage at
least); everything else, the parameter block included, goes to Common, in the same order.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from glint.compiler.compose.linking.emitter import emit
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.units import Unit
from glint.compiler.target.shadertoy import UNIFORM_NAMES

_UNIFORM = re.compile(r"\b(" + "|".join(sorted(UNIFORM_NAMES)) + r")\b")
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_COMMON_TAB = "Paste into the Common tab; the Image tab goes with it."
_IMAGE_TAB = "Paste into the Image tab, with glint's Common tab (the lighting library) beside it."


@dataclass(frozen=True)
class SplitShader:
    common: str  # for the Common tab
    image: str  # for the Image tab


def split_common(scene_name: str, plan: Plan, units: list[Unit], version: str) -> SplitShader:
    image_ids = _image_units(units)
    common = [u for u in units if u.id not in image_ids]
    image = [u for u in units if u.id in image_ids]
    return SplitShader(
        common=emit(scene_name, plan, common, "shadertoy", version, _COMMON_TAB),
        image=emit(scene_name, plan, image, "shadertoy", version, _IMAGE_TAB),
    )


def _image_units(units: list[Unit]) -> set[str]:
    """The units that read a uniform, and every unit that needs one of those."""
    provider = {symbol: unit.id for unit in units for symbol in unit.provides}
    needs = {u.id: {provider[r] for r in u.requires if r in provider} - {u.id} for u in units}
    image = {u.id for u in units if _UNIFORM.search(_COMMENT.sub("", u.body))}
    image.add(next(u.id for u in units if "mainImage" in u.provides))
    grew = True
    while grew:  # whatever needs an Image unit is in the Image tab too
        grew = False
        for uid, wanted in needs.items():
            if uid not in image and wanted & image:
                image.add(uid)
                grew = True
    return image
