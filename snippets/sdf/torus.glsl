/* ---
id = "sdf.torus"
slot = "sdf"
summary = "Exact signed distance to a torus around the y axis (ring of radius major in the xz plane, tube radius minor)"
provides = ["sdTorus"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions)"]
distance = "exact"
formula = 'd(\mathbf{p}) = \left\| \left( \|\mathbf{p}_{xz}\| - R,\; p_y \right) \right\| - r'
--- */
float sdTorus(vec3 p, float major, float minor) {
    // Distance to the ring circle, measured in the half-plane through the axis and p.
    vec2 toRing = vec2(length(p.xz) - major, p.y);
    return length(toRing) - minor;
}
