/* ---
id = "diffuse.toon"
slot = "diffuse"
summary = "Toon: N·L quantised into smoothed bands, plus a Fresnel-like rim toward the light"
provides = ["diffuse", "toonBands"]
requires = ["PI", "Surface", "Dots"]
params = { TOON_BANDS = { type = "float", default = 3.0, range = [1.0, 16.0] }, TOON_SOFTNESS = { type = "float", default = 0.1, range = [0.001, 1.0] }, TOON_RIM = { type = "float", default = 0.5, range = [0.0, 4.0] }, TOON_RIM_EDGE = { type = "float", default = 0.6, range = [0.0, 1.0] }, TOON_RIM_POWER = { type = "float", default = 0.3, range = [0.01, 4.0] } }
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927] }
reference = "diffuse_toon"
error_budget = { max_abs = 1e-5 }
budget_why = "Float32 rounding, amplified where the rim's narrow smoothstep (0.02 wide around TOON_RIM_EDGE) turns on: measured 4.1e-7 absolute there on llvmpipe at the defaults; the budget leaves about 25x."
sources = ["Lighting models (Unity HLSL), 6. Toon shading and rim lighting (Fresnel)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{1}{\pi} \left( \rho\, \frac{\lfloor N x \rfloor + \operatorname{smoothstep}(1 - s, 1, \operatorname{fract}(N x))}{N} + R\, \operatorname{smoothstep}\left( e - 0.01, e + 0.01, (1 - \mathbf{n} \cdot \mathbf{v})(\mathbf{n} \cdot \mathbf{l})^p \right) \right), \quad x = \operatorname{clamp}(\mathbf{n} \cdot \mathbf{l}, 0, 1), \quad N, s, R, e, p = \text{bands, softness, rim, rim edge, rim power}'
--- */
// x in [0, 1] as a staircase of TOON_BANDS steps whose risers are smoothsteps of relative
// width TOON_SOFTNESS (hard cel edges alias; a little softness reads as ink).
float toonBands(float x) {
    float scaled = x * TOON_BANDS;
    float level = floor(scaled);
    return (level + smoothstep(1.0 - TOON_SOFTNESS, 1.0, scaled - level)) / TOON_BANDS;
}

// The rim brightens silhouettes on the lit side: (1 − N·V)·(N·L)^p through a narrow
// smoothstep around TOON_RIM_EDGE, in the light's colour rather than the albedo's. Stylised:
// neither energy conserving nor reciprocal. Divided by π to sit on Lambert's scale.
vec3 diffuse(Surface s, Dots d) {
    float lit = toonBands(clamp(d.NoLsigned, 0.0, 1.0));
    float rim = (1.0 - d.NoV) * pow(max(d.NoL, 1e-6), TOON_RIM_POWER);
    rim = smoothstep(TOON_RIM_EDGE - 0.01, TOON_RIM_EDGE + 0.01, rim) * TOON_RIM;
    return (s.diffuseColor * lit + vec3(rim)) / PI;
}
