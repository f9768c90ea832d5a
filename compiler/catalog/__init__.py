"""The catalog: slots and their contracts, the snippets that fill them (loaded from
`snippets/`), tiers, measured costs and errors, and the `glint catalog` commands (show,
check, info)."""
