/* ---
id = "normal.analytic"
slot = "normal"
summary = "The exact normal of the nearest analytic primitive (every object a sphere, box or plane), no map() taps"
provides = ["calcNormal"]
requires = ["sceneNormal"]
sources = ["Inigo Quilez, sphere and box functions (normals)"]
formula = '\mathbf{n} = \nabla d_k(\mathbf{p}), \quad k = \arg\min_k |d_k(\mathbf{p})|'
--- */
// For a scene of analytic primitives the composer writes sceneNormal: it finds the object whose
// surface p lies on (the least |distance|, each object's own, as the material lookup does) and
// returns that object's gradient in closed form: (p − c)/|p − c| for a sphere, the face's axis
// for a box, n for a plane. Exact up to rounding, where differences of map() are off by their
// step (and cost 4 to 6 evaluations of the whole scene), and correct at every pixel, unlike
// derivative normals at silhouettes.
vec3 calcNormal(vec3 p) {
    return sceneNormal(p);
}
