/* ---
id = "V.smith_ggx_correlated"
slot = "V"
summary = "Height-correlated Smith visibility for GGX, G / (4 NoL NoV), exact form"
provides = ["visibility", "MIN_VIS_DENOM"]
requires = ["Dots"]
domain = { NoV = [0, 1], NoL = [0, 1], a = [0, 1] }
sources = ["lighting-model skill, step 6 method 2", "Heitz 2014", "Filament PBR notes 4.4.2"]
--- */
// Smallest denominator: both terms vanish when NoL = NoV = 0.
#define MIN_VIS_DENOM 1e-5

float visibility(Dots d, float a) {
    float a2 = a * a;
    float gv = d.NoL * sqrt(d.NoV * d.NoV * (1.0 - a2) + a2);
    float gl = d.NoV * sqrt(d.NoL * d.NoL * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, MIN_VIS_DENOM);
}
