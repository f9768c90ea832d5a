/* ---
id = "sdf.capped_cone"
slot = "sdf"
summary = "Exact signed distance to a capped cone along y: radius bottomRadius at y = -halfHeight, topRadius at y = halfHeight"
provides = ["sdCappedCone"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions), capped cone"]
distance = "exact"
formula = 'd(\mathbf{p}) = s \min\left( \|\mathbf{c}_a\|, \|\mathbf{c}_b\| \right), \quad \mathbf{q} = \left( \|\mathbf{p}_{xz}\|, p_y \right), \; \mathbf{c}_a = \text{to the nearer cap}, \; \mathbf{c}_b = \text{to the slanted side}, \; s = -1 \text{ inside}'
--- */
float sdCappedCone(vec3 p, float halfHeight, float bottomRadius, float topRadius) {
    // The profile is a trapezoid in the (radial, height) half-plane.
    vec2 q = vec2(length(p.xz), p.y);
    // To the nearer cap: a segment from the axis to that cap's rim.
    float capRadius = q.y < 0.0 ? bottomRadius : topRadius;
    vec2 toCap = vec2(q.x - min(q.x, capRadius), abs(q.y) - halfHeight);
    // To the slanted side: the segment from the top rim to the bottom rim.
    vec2 topRim = vec2(topRadius, halfHeight);
    vec2 side = vec2(bottomRadius - topRadius, -2.0 * halfHeight);
    // (max: a degenerate cone of height 0 would divide by 0)
    float along = clamp(dot(q - topRim, side) / max(dot(side, side), 1e-12), 0.0, 1.0);
    vec2 toSide = q - topRim - side * along;
    // Inside when below the side line (left of it) and between the caps.
    bool inside = toSide.x < 0.0 && toCap.y < 0.0;
    float d = sqrt(min(dot(toCap, toCap), dot(toSide, toSide)));
    return inside ? -d : d;
}
