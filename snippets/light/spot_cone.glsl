/* ---
id = "light.spot_cone"
slot = "light"
summary = "A spot light's angular falloff: a squared linear ramp in the cosine between the outer and the inner cone"
provides = ["spotCone"]
requires = []
domain = { cosAngle = [-1, 1], cosOuter = [0, 0.999], cosInner = [0, 1] }
reference = "spot_cone"
error_budget = { max_abs = 1e-5 }
budget_why = "A clamp and a square of values in [0, 1]: float32 rounding of (c − cos_outer)/(cos_inner − cos_outer) is a few ulps, except on a ramp as narrow as its 1e-4 floor, where the slope magnifies the rounding of c; 1e-5 bounds that."
sources = ["Filament PBR notes, 5.2.2.2 (spot lights: getAngleAttenuation)", "Lagarde & de Rousiers 2014, Moving Frostbite to PBR, listing 4"]
formula = 'C(c) = \operatorname{clamp}\left( \frac{c - \cos\theta_{\text{outer}}}{\max(\cos\theta_{\text{inner}} - \cos\theta_{\text{outer}}, 10^{-4})}, 0, 1 \right)^2'
--- */
// Squared so the edge of the pool of light fades in smoothly (its slope is 0 at the outer
// cone); the 1e-4 floor makes equal cones a hard edge rather than a division by zero.
float spotCone(float cosAngle, float cosOuter, float cosInner) {
    float t = clamp((cosAngle - cosOuter) / max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
    return t * t;
}
