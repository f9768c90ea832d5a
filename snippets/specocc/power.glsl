/* ---
id = "specocc.power"
slot = "specocc"
summary = "Specular occlusion from AO: clamp((NoV + ao)^a − 1 + ao)"
provides = ["specularOcclusion"]
requires = []
domain = { NoV = [0, 1], ao = [0, 1], a = [0, 1] }
sources = ["lighting-model skill, step 9", "Lagarde and de Rousiers 2014"]
formula = '\text{SO} = \operatorname{clamp}\left( (\mathbf{n} \cdot \mathbf{v} + \text{ao})^{\alpha} - 1 + \text{ao},\ 0,\ 1 \right), \quad \alpha = \text{roughness}^2'
--- */
float specularOcclusion(float NoV, float ao, float a) {
    return clamp(pow(NoV + ao, a) - 1.0 + ao, 0.0, 1.0);
}
