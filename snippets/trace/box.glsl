/* ---
id = "trace.box"
slot = "trace"
summary = "A ray against an axis-aligned box with half extents b centred at the origin: the first hit, the ray's angular clearance from it, the face normal"
provides = ["traceBox", "clearanceBox", "normalBox", "boxSlabs", "cosToArc"]
requires = ["clearanceSphere"]
sources = ["Kay and Kajiya 1986, ray tracing complex scenes (slabs)", "Williams et al. 2005, an efficient and robust ray-box intersection algorithm"]
formula = 't = \max\left(0, \max_i t^{-}_i\right) \text{ if } \max_i t^{-}_i \le \min_i t^{+}_i, \quad t^{\pm}_i = \frac{\pm b_i - o_i}{\omega_i}; \qquad \delta = \pm \min_{e \in \text{silhouette}} \angle(\boldsymbol{\omega}, e)'
--- */
// ro is the ray's origin relative to the box's centre, rd a unit direction.

// The entry and exit parameters of the ray through the box's three slabs, (latest entry,
// earliest exit); the ray meets the box where the first is not past the second. A component of
// rd that is exactly 0 is nudged off 0: the slab's two parameters then become huge with the
// sign of the side ro is on, which is what a ray parallel to a slab needs (inside it for every
// t, or for none), without an inf − inf.
vec2 boxSlabs(vec3 ro, vec3 rd, vec3 b) {
    vec3 dir = mix(rd, vec3(1e-30), equal(rd, vec3(0.0)));
    vec3 m = 1.0 / dir;
    vec3 centre = -m * ro;
    vec3 half_ = abs(m) * b;
    vec3 tNear = centre - half_;
    vec3 tFar = centre + half_;
    return vec2(max(max(tNear.x, tNear.y), tNear.z), min(min(tFar.x, tFar.y), tFar.z));
}

float traceBox(vec3 ro, vec3 rd, vec3 b) {
    vec2 t = boxSlabs(ro, rd, b);
    if (t.x > t.y || t.y < 0.0) return -1.0;
    return max(t.x, 0.0);  // 0: the origin is inside, hit at once as a march would stop
}

// The outward normal of the face nearest p (p on or near the box's surface): the axis on
// which p is relatively furthest out, with p's sign on it.
vec3 normalBox(vec3 p, vec3 b) {
    vec3 q = abs(p) - b;
    if (q.x >= q.y && q.x >= q.z) return vec3(sign(p.x), 0.0, 0.0);
    if (q.y >= q.z) return vec3(0.0, sign(p.y), 0.0);
    return vec3(0.0, 0.0, sign(p.z));
}

// The cosine of the angle from unit d to the nearest point of the great-circle arc from unit a
// to unit e (the arc an edge's ends span as seen from the ray's origin).
float cosToArc(vec3 d, vec3 a, vec3 e) {
    float best = max(dot(d, a), dot(d, e));
    vec3 m = cross(a, e);
    float mm = dot(m, m);
    if (mm < 1e-12) return best;  // the edge is seen end on: its ends are all there is
    m *= inversesqrt(mm);
    float off = dot(d, m);  // sine of d's angle to the arc's plane
    vec3 foot = d - off * m;  // d projected into that plane
    // The foot lies within the arc when it turns from a towards e, and from itself on to e.
    bool within = dot(cross(a, foot), m) >= 0.0 && dot(cross(foot, e), m) >= 0.0;
    return within ? max(best, sqrt(max(1.0 - off * off, 0.0))) : best;
}

// The clearance: the signed angle between the ray and the box's outline seen from ro,
// positive when the ray passes outside. The outline of a convex box is made of its silhouette
// edges, those between a face turned toward ro and one turned away, so the angle to the
// outline is the least angle to one of them, outside or inside alike; the sign is the hit test.
// A box whose entry lies beyond tmax does not count (π: far clear).
//
// Only clearances up to `reach` matter to the caller (a soft shadow's light radius): the box's
// bounding sphere is tested first, and where it clears the ray by more than that its clearance,
// a lower bound of the box's, is returned without the twelve edges.
float clearanceBox(vec3 ro, vec3 rd, vec3 b, float tmax, float reach) {
    float bound = clearanceSphere(ro, rd, length(b), tmax);
    if (bound > reach) return bound;
    vec2 t = boxSlabs(ro, rd, b);
    bool hit = t.x <= t.y && t.y >= 0.0;
    if (hit && t.x > tmax) return 3.14159265;
    // +1 where ro sees the face on the + side of an axis, -1 the - side, 0 neither.
    vec3 facing = vec3(greaterThan(ro, b)) - vec3(lessThan(ro, -b));
    float best = -1.0;  // cosine of the least angle to a silhouette edge so far
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        int k = (i + 2) % 3;
        for (int corner = 0; corner < 4; corner++) {
            float sj = (corner & 1) == 0 ? -1.0 : 1.0;
            float sk = (corner & 2) == 0 ? -1.0 : 1.0;
            // The edge along axis i at (sj·b[j], sk·b[k]) joins the faces sj on j and sk on k.
            if ((facing[j] == sj) == (facing[k] == sk)) continue;
            vec3 a = vec3(0.0);
            a[j] = sj * b[j];
            a[k] = sk * b[k];
            vec3 e = a;
            a[i] = -b[i];
            e[i] = b[i];
            best = max(best, cosToArc(rd, normalize(a - ro), normalize(e - ro)));
        }
    }
    float angle = acos(clamp(best, -1.0, 1.0));
    return hit ? -angle : angle;
}
