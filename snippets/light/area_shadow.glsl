/* ---
id = "light.area_shadow"
slot = "light"
summary = "Shadow of an area light: the mean of shadow rays toward AREA_SHADOW_RAYS² points spread over the light"
provides = ["areaShadow"]
requires = ["shadow", "AREA_SPHERE"]
params = { AREA_SHADOW_RAYS = { type = "int", default = 2, range = [1, 8] } }
sources = ["Cook, Porter & Carpenter 1984, Distributed ray tracing (penumbrae from rays spread over the light)"]
formula = 'S = \frac{1}{n^2} \sum_{i,j} \operatorname{shadow}\left(\mathbf{p},\ \frac{\mathbf{q}_{ij} - \mathbf{p}}{\|\mathbf{q}_{ij} - \mathbf{p}\|}\right), \quad \mathbf{q}_{ij} = \mathbf{c} + \left(\tfrac{2i + 1}{n} - 1\right) \tfrac{\mathbf{r}}{2} + \left(\tfrac{2j + 1}{n} - 1\right) \tfrac{\mathbf{u}}{2}'
--- */
// The penumbra widens with the light's size as the rays part; each ray is the `shadow` slot's
// (soft variants add their own small penumbra, which smooths the steps between rays). One
// ray (AREA_SHADOW_RAYS = 1) is the shadow of the light's centre. A sphere's points lie across
// the way to it, where its outline is.
float areaShadow(vec3 P, vec3 center, vec3 right, vec3 up, int shape) {
    vec3 across = right;
    vec3 along = up;
    if (shape == AREA_SPHERE) {
        vec3 w = normalize(center - P);
        vec3 t = normalize(abs(w.y) < 0.99 ? cross(w, vec3(0.0, 1.0, 0.0)) : cross(w, vec3(1.0, 0.0, 0.0)));
        across = t * length(right);
        along = cross(w, t) * length(right);
    }
    float sum = 0.0;
    for (int i = 0; i < AREA_SHADOW_RAYS; i++) {
        for (int j = 0; j < AREA_SHADOW_RAYS; j++) {
            vec2 q = (2.0 * vec2(i, j) + 1.0) / float(AREA_SHADOW_RAYS) - 1.0;
            vec3 toPoint = center + 0.5 * (q.x * across + q.y * along) - P;
            float d = length(toPoint);
            sum += shadow(P, toPoint / max(d, 1e-6), 0.02, d);
        }
    }
    return sum / float(AREA_SHADOW_RAYS * AREA_SHADOW_RAYS);
}
