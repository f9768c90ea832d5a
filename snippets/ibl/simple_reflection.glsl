/* ---
id = "ibl.simple_reflection"
slot = "ibl"
summary = "Environment seen along the mirror direction, weighted by Fresnel(NoV) and specular occlusion"
provides = ["environmentLight"]
requires = ["Surface", "F", "env", "specocc"]
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
