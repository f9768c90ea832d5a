// Common: what every pass shares.
vec3 tint() { return vec3(1.0, 0.6, 0.2); }
