"""Code generation: the scene's own units (its distance function and objects, materials, lights,
`shade`, `mainImage`), the closed-form traces and bounds of analytic scenes, the user's GLSL
file as a unit, and the scene values a page can turn (knobs)."""
