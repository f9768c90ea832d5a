/* ---
id = "ibl.simple_reflection"
slot = "ibl"
summary = "Environment seen along the mirror direction, weighted by Fresnel(NoV) and specular occlusion"
provides = ["environmentLight"]
requires = ["Surface", "F", "env", "specocc"]
error_budget = { max_abs = 0.45, rms = 0.09 }
budget_why = "No prefiltering: a 1 − 0.7·roughness dimming stands in for the lobe's blur. Against the GGX lobe integrated over the gradient sky: up to 0.41 (grazing) and RMS 0.075 in radiance, 0.02 below roughness 0.05 (measured). The budget is that design error."
sources = ["lighting-model skill, complete code template (environment reflection)"]
formula = 'L_{\text{spec}} = F(\mathbf{n} \cdot \mathbf{v})\, L_{\text{env}}(\mathbf{r})\, \text{SO}\, (1 - 0.7\, \text{roughness}), \quad \mathbf{r} = 2 (\mathbf{n} \cdot \mathbf{v})\, \mathbf{n} - \mathbf{v}'
--- */
// No prefiltering: rough surfaces dim the reflection instead of blurring it.
vec3 environmentLight(Surface s, float ao) {
    vec3 R = reflect(-s.V, s.N);
    vec3 F = fresnel(s.f0, s.NoV);
    float occlusion = specularOcclusion(s.NoV, ao, s.a);
    return F * environment(R) * occlusion * (1.0 - s.roughness * 0.7);
}
