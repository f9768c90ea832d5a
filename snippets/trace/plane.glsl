/* ---
id = "trace.plane"
slot = "trace"
summary = "A ray against the half-space below a plane (unit normal n, offset h): the first hit, and the ray's angular clearance from it"
provides = ["tracePlane", "clearancePlane"]
requires = []
sources = ["lighting-model skill, complete code template (the ground plane)"]
formula = 't = -\frac{\mathbf{o} \cdot \mathbf{n} + h}{\boldsymbol{\omega} \cdot \mathbf{n}}; \qquad \delta = \arcsin(\boldsymbol{\omega} \cdot \mathbf{n}) + \arcsin \frac{\mathbf{o} \cdot \mathbf{n} + h}{t_{\max}}'
--- */
// The solid is the half-space where dot(p, n) + h < 0 (sdPlane's inside).
float tracePlane(vec3 ro, vec3 rd, vec3 n, float h) {
    float height = dot(ro, n) + h;
    if (height < 0.0) return 0.0;  // the origin is inside: hit at once, as a march would stop
    float rate = dot(rd, n);
    return rate < 0.0 ? height / -rate : -1.0;
}

// The clearance: the signed angle between the ray and the highest point of the plane within
// tmax, seen from ro. Points of the plane at distance s lie asin(height / s) below the
// horizontal, so the highest within reach are at s = tmax; the ray's own elevation above the
// horizontal is asin(ω·n). At tmax = ∞ this is the elevation: a half-space hides the lower half
// of the sky from any point above it. Inside (height < 0) the ray is hidden outright.
float clearancePlane(vec3 ro, vec3 rd, vec3 n, float h, float tmax) {
    float height = dot(ro, n) + h;
    if (height < 0.0) return -3.14159265;
    return asin(clamp(dot(rd, n), -1.0, 1.0)) + asin(min(height / tmax, 1.0));
}
