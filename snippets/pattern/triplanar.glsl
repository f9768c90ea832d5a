/* ---
id = "pattern.triplanar"
slot = "pattern"
summary = "A picture wrapped onto any surface: its three planar projections blended by the normal, decoded to linear colour"
provides = ["triplanar"]
requires = []
sources = ["Geiss 2007, GPU Gems 3, ch. 1.5 (triplanar texturing)", "Inigo Quilez, biplanar and triplanar mapping (2020)"]
formula = '\mathbf{c} = \frac{\sum_{a \in \{x,y,z\}} w_a\, T(\mathbf{p}_{\perp a} / s)^{2.2}}{\sum_a w_a}, \quad w_a = |n_a|^4'
--- */
// A distance field has no texture coordinates: the picture is projected along each axis and
// the three samples (x: the picture seen along x, on the zy plane; y: on xz; z: on xy) are
// blended by how squarely the surface faces that axis (|n|⁴ keeps the seams narrow). The scene's
// code samples the channel (a sampler as a parameter is not portable: naga refuses it).
// ShaderToy pictures are sRGB: 2.2 is the gamma the output step puts back.
vec3 triplanar(vec3 x, vec3 y, vec3 z, vec3 n) {
    vec3 w = abs(n);
    w *= w;
    w *= w;
    w /= max(w.x + w.y + w.z, 1e-6);
    vec3 c = x * w.x + y * w.y + z * w.z;
    return pow(max(c, 0.0), vec3(2.2));
}
