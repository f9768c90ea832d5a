/* ---
id = "sdf.sphere"
slot = "sdf"
summary = "Signed distance to a sphere centred at the origin"
provides = ["sdSphere"]
requires = []
sources = ["lighting-model skill, complete code template"]
formula = 'd(\mathbf{p}) = \|\mathbf{p}\| - r'
--- */
float sdSphere(vec3 p, float radius) {
    return length(p) - radius;
}
