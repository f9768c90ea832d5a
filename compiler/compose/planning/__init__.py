"""Planning: which slots the scene's units reach and why (scene_slots), the variant for each
(planner, from the tier table, the scene's overrides or a budget), the result as data (plan),
`--explain`, and baking the parameter values the scene sets or implies (bake, spherical
harmonics of the sky)."""
