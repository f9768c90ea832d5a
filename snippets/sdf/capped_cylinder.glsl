/* ---
id = "sdf.capped_cylinder"
slot = "sdf"
summary = "Exact signed distance to a cylinder along y with flat caps at y = -halfHeight and y = halfHeight"
provides = ["sdCappedCylinder"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions)"]
distance = "exact"
formula = 'd(\mathbf{p}) = \|\max(\mathbf{q}, 0)\| + \min\left(\max(q_1, q_2), 0\right), \quad \mathbf{q} = \left( \|\mathbf{p}_{xz}\|, |p_y| \right) - (r, h)'
--- */
float sdCappedCylinder(vec3 p, float radius, float halfHeight) {
    // A 2D box in the (radial, height) half-plane: the side and the caps are its edges.
    vec2 q = abs(vec2(length(p.xz), p.y)) - vec2(radius, halfHeight);
    return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0);
}
