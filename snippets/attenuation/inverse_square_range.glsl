/* ---
id = "attenuation.inverse_square_range"
slot = "attenuation"
summary = "Physical 1/d² falloff, windowed smoothly to zero at the light's range"
provides = ["attenuation", "ATTEN_MIN_DIST"]
requires = []
domain = { dist = [0.01, 100], range = [0.1, 100] }
reference = "attenuation_inverse_square_windowed"
error_budget = { max_abs = 2e-3, max_rel = 1e-4 }
budget_why = "Next to the light the values reach 1e4, and float32 leaves a few 1e-4 (measured 5.5e-4 at d = 0.01); near the range 1 − q⁴ cancels, up to 1e-4 of a tiny value by analysis (measured 1.5e-5)."
sources = ["Karis 2013, Real Shading in Unreal Engine 4, eq. 9", "Filament, shaders/src/light_punctual.fs (getDistanceAttenuation)", "Lagarde & de Rousiers 2014, Moving Frostbite to PBR, 3.1.2"]
formula = 'A(d) = \begin{cases} \dfrac{\operatorname{clamp}\left( 1 - (d / r)^4, 0, 1 \right)^2}{\max(d^2, 0.01^2)} & d < r \\ 0 & d \ge r \end{cases}, \quad r = \text{range}'
--- */
// Closest distance the falloff is evaluated at: 1 cm in a scene in metres. It caps the factor
// at 1/ATTEN_MIN_DIST² = 1e4 next to the light, where 1/d² would reach +∞ (a point light has no
// size; a shaded point that close is inside any real bulb). Its square, 1e-4, is also above
// mediump's smallest normal number (6.1e-5), so the floor survives a half-float GPU.
#define ATTEN_MIN_DIST 0.01

// (saturate(1 − (d/r)⁴))² / max(d², ε²): inverse square, times a window that is 1 at the light
// and falls to 0 with zero slope at d = range, so a light's influence ends at its range without a
// visible edge and a renderer can cull beyond it. Past the range, a range of 0 or below, and an
// infinite dist all return exactly 0 (the window is 0 there already; the branch also keeps d/r
// from being 0/0 when both are 0). In float32, 1 − q⁴ cancels as d nears the range: there the
// result is small (under 1e-6 for the domain's ranges) and off by up to 1e-4 of itself; next to
// the light the values reach 1e4 and the absolute error is a few 1e-4 (relative 1e-7).
float attenuation(float dist, float range) {
    if (!(dist < range)) return 0.0;
    float q = dist / range;
    float q2 = q * q;
    float window = clamp(1.0 - q2 * q2, 0.0, 1.0);
    return window * window / max(dist * dist, ATTEN_MIN_DIST * ATTEN_MIN_DIST);
}
