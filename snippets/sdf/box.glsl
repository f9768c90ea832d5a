/* ---
id = "sdf.box"
slot = "sdf"
summary = "Signed distance to an axis-aligned box with half extents b, centred at the origin"
provides = ["sdBox"]
requires = []
sources = ["Inigo Quilez, distance functions"]
formula = 'd(\mathbf{p}) = \|\max(\mathbf{q}, 0)\| + \min\left( \max(q_x, q_y, q_z), 0 \right), \quad \mathbf{q} = |\mathbf{p}| - \mathbf{b}'
--- */
float sdBox(vec3 p, vec3 b) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
