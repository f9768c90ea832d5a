"""Mesh scenes: a vertex and a fragment program per material through the same planner and
emitter (pipeline), each stage's generated code (code), the built-in meshes and their placing
(geometry), the view and projection matrices (camera)."""
