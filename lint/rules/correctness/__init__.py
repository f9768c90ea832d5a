"""C, correctness. One module per rule:

- C001, C002: glslangValidator's errors and warnings, the file compiled as its target wraps it
  (ShaderToy's prelude and `main`), at the user's line and column, with a hint for the mistakes
  people make most (shared code in `_glslang`).
- C003-C006: what stops glint's own front end (unreadable bytes, preprocessor and syntax
  errors, input too large or too deep to analyse); these run whether or not the file parsed.
- C101-C103: data flow. Reads of values that were never written, and a mainImage that can
  return without writing its colour. Built on the definite-assignment analysis in
  `analysis/flow.py`, which stays silent where it cannot follow the code (shared code in
  `_data_flow`).
"""
