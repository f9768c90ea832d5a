/* ---
id = "specocc.power"
slot = "specocc"
summary = "Specular occlusion from AO: clamp((NoV + ao)^a − 1 + ao)"
provides = ["specularOcclusion"]
requires = []
domain = { NoV = [0.0001, 1], ao = [0, 1], a = [0, 1] }
reference = "specular_visible_fraction"
error_budget = { max_abs = 1.0, rms = 0.25 }
budget_why = "A fit of the lobe's visible share, not an integral: RMS 0.21 against the GGX lobe seen through the AO's cone (measured), up to 1 at corners such as a mirror facing along N, which sees through any cone but the fit calls occluded; the budget is that design error."
sources = ["lighting-model skill, step 9", "Lagarde and de Rousiers 2014"]
formula = '\text{SO} = \operatorname{clamp}\left( (\mathbf{n} \cdot \mathbf{v} + \text{ao})^{\alpha} - 1 + \text{ao},\ 0,\ 1 \right), \quad \alpha = \text{roughness}^2'
--- */
float specularOcclusion(float NoV, float ao, float a) {
    return clamp(pow(NoV + ao, a) - 1.0 + ao, 0.0, 1.0);
}
