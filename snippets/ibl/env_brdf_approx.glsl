/* ---
id = "ibl.env_brdf_approx"
slot = "ibl"
summary = "Environment along the mirror direction times Karis's analytic split-sum fit f0·A + B, with specular occlusion"
provides = ["environmentLight", "envBRDFApprox"]
requires = ["Surface", "env", "specocc"]
error_budget = { max_abs = 0.55 }
budget_why = "Karis's fit was made for a table with a different masking term: against the split sum with height-correlated Smith, f0·A + B is off by up to 0.544 (f0 = 1, roughness 1, grazing), 0.082 for f0 = 0.04; the budget is that design error."
sources = [
    "lighting-model skill, common variants (IBL: EnvBRDFApprox)",
    "Karis 2014, Physically Based Shading on Mobile (EnvBRDFApprox)",
    "Karis 2013, Real Shading in Unreal Engine 4 (split sum)",
]
formula = 'L_{\text{spec}} = (F_0 A + B)\, L_{\text{env}}(\mathbf{r})\, \text{SO}, \quad (A, B) = (-1.04, 1.04)\left( \min(c_x^2, 2^{-9.28\, \mathbf{n} \cdot \mathbf{v}})\, c_x + c_y \right) + (c_z, c_w), \quad \mathbf{c} = \text{roughness}\,(-1, -0.0275, -0.572, 0.022) + (1, 0.0425, 1.04, -0.04), \quad \mathbf{r} = 2 (\mathbf{n} \cdot \mathbf{v})\, \mathbf{n} - \mathbf{v}'
--- */
// The split sum (Karis 2013) factors specular environment light into the environment seen
// around the mirror direction times the BRDF's directional albedo, f0·A + B. Here A and B
// come from Karis's analytic fit instead of a lookup table, and the environment is sampled
// once along R without prefiltering (fine for a smooth sky, too sharp for a rough mirror of
// a detailed one).
//
// Error of (A, B) against the float64 split sum with GGX, height-correlated Smith and Schlick
// (compiler/verify/references/environment.dfg_split_sum), roughness and NoV in [0, 1]: see
// tests/verify/test_environment_light.py. The fit was made for a table with a different masking
// term, so it is close at normal incidence and far off at grazing angles on rough surfaces,
// where height-correlated Smith keeps much more energy: f0·A + B off by up to 0.55 (metals,
// NoV → 0, roughness 1), 0.08 for f0 = 0.04. The GPU gives the same (A, B) as the float32
// evaluator to 2e-7, NoV just outside [0, 1] included. A dips to −0.044 for a grazing mirror
// (f0·A + B up to 1.042 there) and B to −0.0024 at roughness 1: f0·A + B stays ≥ 0 for
// f0 ≥ 0.04, not quite for f0 = 0.

// (A, B) such that the directional albedo is f0·A + B. Perceptual roughness, as Karis fits it.
vec2 envBRDFApprox(float NoV, float roughness) {
    vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float grazing = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
    return vec2(-1.04, 1.04) * grazing + r.zw;
}

vec3 environmentLight(Surface s, float ao) {
    vec3 R = reflect(-s.V, s.N);
    vec2 AB = envBRDFApprox(s.NoV, s.roughness);
    float occlusion = specularOcclusion(s.NoV, ao, s.a);
    return (s.f0 * AB.x + AB.y) * environment(R) * occlusion;
}
