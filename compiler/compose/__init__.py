"""Scene to shader, in one direction: the scene model, the scene's own generated code, the
plan (which slots, which variants), the resolver, parameter baking, pruning and the emitter.
`pipeline.compose_scene` runs the stages in order."""
