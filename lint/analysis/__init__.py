"""Analyses that rules share, computed once per file: the semantic model (scopes, types and
value ranges of expressions) and data flow."""
