"""Tools over the catalog that compose a snippet to show it: `glint catalog show` (show: the
snippet with everything it needs as one block) and the same block as HLSL or MSL (cross). They
sit above the composer, which they use; nothing below imports them."""
