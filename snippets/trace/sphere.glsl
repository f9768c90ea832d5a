/* ---
id = "trace.sphere"
slot = "trace"
summary = "A ray against a sphere centred at the origin: the first hit, and the ray's angular clearance from it"
provides = ["traceSphere", "clearanceSphere"]
requires = []
sources = ["Haines, Günther, Akenine-Möller, Precision Improvements for Ray/Sphere Intersection (Ray Tracing Gems, 2019)", "Inigo Quilez, sphere functions (soft shadow of a sphere)"]
formula = 't = \frac{c}{-b + \sqrt{r^2 - \|\mathbf{o} - b\,\boldsymbol{\omega}\|^2}}, \quad b = \mathbf{o} \cdot \boldsymbol{\omega}, \quad c = \|\mathbf{o}\|^2 - r^2; \qquad \delta = \angle(\boldsymbol{\omega}, -\mathbf{o}) - \arcsin \frac{r}{\|\mathbf{o}\|}'
--- */
// ro is the ray's origin relative to the sphere's centre, rd a unit direction.
//
// The hit. The ray's closest approach to the centre is q = ro − b·rd, b = ro·rd, so the chord's
// half length is √(r² − |q|²): written that way, not as √(b² − c), it keeps its precision when
// the sphere is small and far (b² and c then agree in most of their digits). The near root
// −b − √h is taken as c / (−b + √h), its exact rewrite without the cancellation.
float traceSphere(vec3 ro, vec3 rd, float r) {
    float b = dot(ro, rd);
    vec3 q = ro - b * rd;
    float h = r * r - dot(q, q);
    float c = dot(ro, ro) - r * r;
    if (c < 0.0) return 0.0;  // the origin is inside: hit at once, as a march would stop
    if (h < 0.0 || b > 0.0) return -1.0;  // misses, or the sphere lies behind
    return c / (-b + sqrt(h));
}

// The clearance: the signed angle between the ray and the sphere's outline seen from ro,
// positive when the ray passes outside it. The outline is a circle of angular radius
// asin(r / |ro|) about the direction to the centre, so the clearance is the angle to the centre
// minus that radius: exact, where an SDF march only samples h/t along the ray. The angle to
// the centre is taken as atan(|ω × c|, ω·c), accurate at small angles where acos is not. A
// sphere wholly beyond tmax does not count (π: far clear).
float clearanceSphere(vec3 ro, vec3 rd, float r, float tmax) {
    float dist = max(length(ro), 1e-20);  // at the centre itself the ray is inside
    if (dist - r > tmax) return 3.14159265;
    vec3 toCentre = -ro;
    float centre = atan(length(cross(rd, toCentre)), dot(rd, toCentre));
    return centre - asin(min(r / dist, 1.0));
}
