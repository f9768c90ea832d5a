/* ---
id = "sdf.capsule"
slot = "sdf"
summary = "Exact signed distance to a capsule: the segment from (0,-halfLength,0) to (0,halfLength,0) grown by radius"
provides = ["sdCapsule"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions)"]
distance = "exact"
formula = 'd(\mathbf{p}) = \left\| \mathbf{p} - \left(0,\, \operatorname{clamp}(p_y, -h, h),\, 0\right) \right\| - r'
--- */
float sdCapsule(vec3 p, float halfLength, float radius) {
    // The nearest point of the axis segment is p's height clamped to the segment.
    vec3 fromAxis = p - vec3(0.0, clamp(p.y, -halfLength, halfLength), 0.0);
    return length(fromAxis) - radius;
}
