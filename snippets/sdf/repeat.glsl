/* ---
id = "sdf.repeat"
slot = "sdf"
summary = "Finite domain repetition: p in the frame of its nearest copy on a grid of count copies, spacing apart, centred on the origin"
provides = ["opRepeat"]
requires = []
sources = ["Inigo Quilez, domain repetition (finite repetition)"]
formula = '\mathbf{q} = \mathbf{p} - \mathbf{s} \odot (\mathbf{i} - \mathbf{m}), \quad \mathbf{i} = \operatorname{clamp}\left(\left\lfloor \mathbf{p} \oslash \mathbf{s} + \mathbf{m} + \tfrac12 \right\rfloor, 0, \mathbf{n} - 1\right), \quad \mathbf{m} = \tfrac{\mathbf{n} - 1}{2}'
--- */
vec3 opRepeat(vec3 p, vec3 spacing, vec3 count) {
    // Copies sit at (i - mid) * spacing for i = 0 .. count - 1; the nearest one is taken. An
    // axis with count 1 is not repeated (its spacing may be 0: the clamp keeps i at 0).
    vec3 mid = 0.5 * (count - 1.0);
    vec3 i = clamp(floor(p / max(spacing, vec3(1e-6)) + mid + 0.5), vec3(0.0), count - 1.0);
    return p - spacing * (i - mid);
}
