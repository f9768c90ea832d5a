"""N, numerical hazards: builtins called outside their domain, divisions by values that reach
zero, degenerate normalize, and constant arguments that make clamp/smoothstep undefined.

Every rule asks the semantic model for value ranges instead of matching text, so
`pow(max(dot(N, H), 0.0), s)` is clean and `pow(dot(N, H), s)` is not. A range the model cannot
bound is unknown and never reported: a finding needs evidence, a finite bound reached by the
value (dot of unit vectors in [-1, 1], a length that starts at 0) or a value that is a raw dot
product, length or cross product. One module per rule; shared helpers in `_common`.
"""
