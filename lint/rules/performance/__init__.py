"""PF, performance: work the GPU does for nothing (pow for a square, loop-invariant calls inside
a march loop, normalize of what is already unit length). Findings are advice (info). One module
per rule; shared helpers in `_common`, the shading-code vocabulary in `..lighting._terms`."""
