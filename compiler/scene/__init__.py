"""The scene model: what a scene file says (camera, objects and their shapes, the user's own
distance function, materials, lights, environment, quality, post), validated by pydantic, with
one clear message naming the first bad key. Its own layer, below the catalog and the composer:
it knows nothing of snippets or code generation, and everything that reads a scene (the
composer, the renderer's mesh path, the docs site's scene reference) imports it from here.

- `model`: the scene and its tables; `load_scene`, `scene_from_dict`.
- `shapes`: the objects' shapes and CSG groups (their parameters, not their code).
- `values`: the value types every table shares (colours, vectors, units, finite floats).
"""
