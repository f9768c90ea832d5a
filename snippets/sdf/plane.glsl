/* ---
id = "sdf.plane"
slot = "sdf"
summary = "Signed distance to an infinite plane with unit normal n, offset h from the origin"
provides = ["sdPlane"]
requires = []
sources = ["lighting-model skill, complete code template"]
formula = 'd(\mathbf{p}) = \mathbf{p} \cdot \mathbf{n} + h'
--- */
float sdPlane(vec3 p, vec3 n, float h) {
    return dot(p, n) + h;
}
