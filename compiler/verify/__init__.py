"""Checking that snippets do what they say: float64 references, GPU probes, CPU evaluation of
a snippet and its half-precision survival."""
