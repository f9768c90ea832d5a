"""S, style and the linter's own housekeeping. S001 depends on what every other rule found, so
the runner calls `s001_unused_suppression.unused_suppressions` after them; the rule class
registers the code and its docs."""
