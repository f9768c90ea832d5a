/* ---
id = "sdf.ellipsoid"
slot = "sdf"
summary = "Lower bound (not exact) of the signed distance to an axis-aligned ellipsoid with semi-axes radii: never larger than the true distance, zero on the surface; march it without over-relaxation"
provides = ["sdEllipsoid"]
requires = []
sources = ["Inigo Quilez, distance functions (iquilezles.org/articles/distfunctions), ellipsoid", "Inigo Quilez, ellipsoid SDF (iquilezles.org/articles/ellipsoids)"]
distance = "bound"
formula = 'd(\mathbf{p}) = \begin{cases} \min(d_q, d_l) & k_0 \ge 1 \\ \max(d_q, d_l) & k_0 < 1 \end{cases}, \quad k_0 = \left\|\frac{\mathbf{p}}{\mathbf{r}}\right\|, \; k_1 = \left\|\frac{\mathbf{p}}{\mathbf{r}^2}\right\|, \; d_q = \frac{k_0 (k_0 - 1)}{k_1}, \; d_l = (k_0 - 1) \min_i r_i'
--- */
float sdEllipsoid(vec3 p, vec3 radii) {
    float k0 = length(p / radii);
    float k1 = length(p / (radii * radii));
    float smallest = min(radii.x, min(radii.y, radii.z));
    // A rigorous bound: k0 grows at most 1 / smallest per unit step, so this is 1-Lipschitz
    // and zero on the surface, hence never larger than the distance.
    float linear = (k0 - 1.0) * smallest;
    // Quilez's first-order estimate: tighter near the surface but not a bound everywhere
    // (k0 / k1 lies in [min r, max r]; at the centre 0 / 0, where it takes the smallest radius).
    float quotient = (k0 - 1.0) * max(k0 / max(k1, 1e-30), smallest);
    // Outside both are >= 0 and the smaller is still a bound; inside both are <= 0 and the
    // one nearer zero is. Either way the result is a bound because `linear` is.
    return k0 >= 1.0 ? min(quotient, linear) : max(quotient, linear);
}
