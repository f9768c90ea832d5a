/* ---
id = "pattern.checker"
slot = "pattern"
summary = "Checkerboard on the xz plane: 0 or 1 per unit cell"
provides = ["checker"]
requires = []
sources = ["lighting-model skill, complete code template"]
formula = 'c(\mathbf{p}) = \left( \lfloor p_x \rfloor + \lfloor p_z \rfloor \right) \bmod 2'
--- */
float checker(vec3 p) {
    return mod(floor(p.x) + floor(p.z), 2.0);
}
