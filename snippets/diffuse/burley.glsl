/* ---
id = "diffuse.burley"
slot = "diffuse"
summary = "Burley (Disney) diffuse: Lambert with a retro-reflective rim from roughness"
provides = ["diffuse", "burleyTail"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0, 1] }
reference = "diffuse_burley"
error_budget = { max_abs = 2e-6 }
budget_why = "Float32 rounding only: measured 9.1e-8 absolute on llvmpipe (worst at roughness 1, N·L = 1, grazing N·V); the budget leaves about 20x for other drivers."
sources = ["Burley 2012, Physically-Based Shading at Disney, 5.3", "Filament PBR notes, 4.7.1"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} (\mathbf{n} \cdot \mathbf{l}) \left( 1 + (F_{90} - 1)(1 - \mathbf{n} \cdot \mathbf{l})^5 \right) \left( 1 + (F_{90} - 1)(1 - \mathbf{n} \cdot \mathbf{v})^5 \right), \quad F_{90} = 0.5 + 2\,\text{roughness}\,(\mathbf{v} \cdot \mathbf{h})^2'
--- */
// Two Schlick-like factors toward F90 = 0.5 + 2·roughness·(L·H)²: smooth surfaces darken at
// grazing angles, rough ones brighten (retro-reflection). Not energy conserving: it reflects
// up to about 1.56 of uniform light for rough surfaces seen at grazing angles.
float burleyTail(float cosine, float f90) {
    float m = 1.0 - cosine;
    float m2 = m * m;
    return 1.0 + (f90 - 1.0) * m2 * m2 * m;
}

vec3 diffuse(Surface s, Dots d) {
    float f90 = 0.5 + 2.0 * s.roughness * d.VoH * d.VoH;
    float scatter = burleyTail(d.NoL, f90) * burleyTail(d.NoV, f90);
    return s.diffuseColor * (scatter * d.NoL / PI);
}
