/* ---
id = "sdf.round_box"
slot = "sdf"
summary = "Exact signed distance to a box with outer half extents halfSize whose edges and corners are rounded with radius rounding (rounding <= min(halfSize))"
provides = ["sdRoundBox"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions)"]
distance = "exact"
formula = 'd(\mathbf{p}) = \|\max(\mathbf{q}, 0)\| + \min\left( \max(q_x, q_y, q_z), 0 \right) - r, \quad \mathbf{q} = |\mathbf{p}| - \mathbf{b} + r'
--- */
float sdRoundBox(vec3 p, vec3 halfSize, float rounding) {
    // The distance to the inner box (shrunk by rounding), grown back by rounding.
    vec3 q = abs(p) - (halfSize - rounding);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - rounding;
}
