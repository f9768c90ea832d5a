"""PF, performance: work the GPU does for nothing (pow for a square, loop-invariant calls inside
a march loop, normalize of what is already unit length). Findings are advice (info). One module
per rule; shared helpers in `_common`; the analyses they build on (functions and locals,
constant folding, the semantic model) in `lint/analysis`."""
