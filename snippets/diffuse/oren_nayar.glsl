/* ---
id = "diffuse.oren_nayar"
slot = "diffuse"
summary = "Oren-Nayar, full model (direct term with C1..C3 and interreflection), made safe"
provides = ["diffuse", "orenNayarCosPhi"]
requires = ["PI", "Surface", "Dots"]
domain = { NoL = [-1, 1], NoV = [0.0001, 1], phi = [0, 3.1415927], roughness = [0, 1] }
reference = "diffuse_oren_nayar"
error_budget = { max_abs = 2e-4 }
budget_why = "Float32 rounding of the acos, sin/cos and tan terms: measured 7.0e-5 absolute on llvmpipe, worst at roughness 1 with N·L ≈ N·V ≈ 0.11; the budget is about 3x that."
sources = ["Oren and Nayar 1994, Generalization of Lambert's reflectance model, eqs. 30 and 39", "Lighting models (Unity HLSL), 7. Oren-Nayar", "kchapelier, lighting technique notes (Oren Nayar)"]
formula = 'f_d\,(\mathbf{n} \cdot \mathbf{l}) = \frac{\rho}{\pi} (\mathbf{n} \cdot \mathbf{l}) \left( C_1 + \cos\phi\, C_2 \tan\beta + (1 - |\cos\phi|)\, C_3 \tan\tfrac{\alpha + \beta}{2} + 0.17\,\rho \frac{\sigma^2}{\sigma^2 + 0.13} \left( 1 - \cos\phi \left( \tfrac{2\beta}{\pi} \right)^2 \right) \right), \quad C_1 = 1 - \frac{0.5\sigma^2}{\sigma^2 + 0.33}, \quad C_2 = \frac{0.45\sigma^2}{\sigma^2 + 0.09} \begin{cases} \sin\alpha & \cos\phi \ge 0 \\ \sin\alpha - \left( \tfrac{2\beta}{\pi} \right)^3 & \cos\phi < 0 \end{cases}, \quad C_3 = \frac{0.125\sigma^2}{\sigma^2 + 0.09} \left( \frac{4\alpha\beta}{\pi^2} \right)^2, \quad \alpha = \max(\theta_l, \theta_v), \quad \beta = \min(\theta_l, \theta_v), \quad \sigma = \text{roughness}'
--- */
// Cosine of the azimuth between L and V around N, from the dot products; 0 where L or V lies
// along N (the azimuth is undefined there, and every term that uses it is multiplied by 0).
float orenNayarCosPhi(Dots d) {
    float sines = sqrt(max(1.0 - d.NoL * d.NoL, 0.0) * max(1.0 - d.NoV * d.NoV, 0.0));
    return sines > 1e-6 ? clamp((d.LoV - d.NoL * d.NoV) / sines, -1.0, 1.0) : 0.0;
}

// The roughness σ (radians, standard deviation of the facet slopes) is the perceptual
// roughness. The angles come from acos of clamped cosines (acos of 1 + 1e-7 is NaN), and
// tan β from sin/cos with cos floored: β < π/2 always, since NoV >= MIN_NOV.
vec3 diffuse(Surface s, Dots d) {
    if (d.NoL <= 0.0) return vec3(0.0);
    float s2 = s.diffuseRoughness * s.diffuseRoughness;
    float thetaL = acos(clamp(d.NoL, 0.0, 1.0));
    float thetaV = acos(clamp(d.NoV, 0.0, 1.0));
    float alpha = max(thetaL, thetaV);
    float beta = min(thetaL, thetaV);
    float cosPhi = orenNayarCosPhi(d);
    float betaTerm = 2.0 * beta / PI;
    float c1 = 1.0 - 0.5 * s2 / (s2 + 0.33);
    float c2 = 0.45 * s2 / (s2 + 0.09)
        * (cosPhi >= 0.0 ? sin(alpha) : sin(alpha) - betaTerm * betaTerm * betaTerm);
    float c3 = 0.125 * s2 / (s2 + 0.09) * pow(4.0 * alpha * beta / (PI * PI), 2.0);
    float tanBeta = sin(beta) / max(cos(beta), 1e-4);
    float halfSum = 0.5 * (alpha + beta);
    float tanHalfSum = sin(halfSum) / max(cos(halfSum), 1e-4);
    float direct = c1 + cosPhi * c2 * tanBeta + (1.0 - abs(cosPhi)) * c3 * tanHalfSum;
    // Light bounced between facets: grows with the albedo, per channel.
    vec3 bounce = 0.17 * s.diffuseColor * (s2 / (s2 + 0.13))
        * (1.0 - cosPhi * betaTerm * betaTerm);
    return s.diffuseColor * (direct + bounce) * (d.NoL / PI);
}
