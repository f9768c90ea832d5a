/* ---
id = "D.ggx"
slot = "D"
summary = "GGX / Trowbridge-Reitz normal distribution"
provides = ["distribution"]
requires = ["PI"]
domain = { NoH = [0, 1], a = [0, 1] }
sources = ["lighting-model skill, step 5", "Walter et al. 2007"]
--- */
// D(h) = a² / (π ((n·h)² (a² − 1) + 1)²). Takes a = roughness², never roughness.
float distribution(float NoH, float a) {
    float a2 = a * a;
    float d = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}
