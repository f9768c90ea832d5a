/* ---
id = "irradiance.sh9"
slot = "irradiance"
summary = "Irradiance/π from nine spherical-harmonic radiance coefficients (order 2)"
provides = ["irradiance", "SH9_K0", "SH9_K1", "SH9_K2", "SH9_K20", "SH9_K22"]
requires = []
domain = { n0 = [-1, 1], n1 = [-1, 1], n2 = [-1, 1] }
reference = "irradiance_gradient"
error_budget = { max_abs = 2e-7 }
budget_why = "Bands 3 and up carry nothing for the smooth gradient sky, so only float32 rounding is left: measured 6.8e-8 on llvmpipe; the budget is about 3x that."
sources = [
    "lighting-model skill, common variants (IBL: SH irradiance)",
    "Ramamoorthi and Hanrahan 2001, An Efficient Representation for Irradiance Environment Maps",
    "Sloan 2008, Stupid Spherical Harmonics Tricks (basis constants)",
]
formula = '\frac{E(\mathbf{n})}{\pi} = \max\left( 0,\ \sum_{l=0}^{2} \sum_{m=-l}^{l} \frac{\hat{A}_l}{\pi} L_{lm} Y_{lm}(\mathbf{n}) \right), \quad \frac{\hat{A}_0}{\pi} = 1, \quad \frac{\hat{A}_1}{\pi} = \frac{2}{3}, \quad \frac{\hat{A}_2}{\pi} = \frac{1}{4}'
# SH_C0..SH_C8: radiance coefficients L00, L1-1 (y), L10 (z), L11 (x), L2-2 (xy), L2-1 (yz),
# L20 (3z²−1), L21 (xz), L22 (x²−y²), from compiler/compose/spherical_harmonics.project_sh9. The
# defaults are env.gradient's default sky; tests/verify/test_environment_light.py re-projects it.
[params.SH_C0]
type = "vec3"
default = [2.30419, 2.7473035, 3.3676623]
[params.SH_C1]
type = "vec3"
default = [-0.306998, -0.153499, 0.1023327]
[params.SH_C2]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C3]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C4]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C5]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C6]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C7]
type = "vec3"
default = [0.0, 0.0, 0.0]
[params.SH_C8]
type = "vec3"
default = [0.0, 0.0, 0.0]
--- */
// E(n)/π = Σ (Â_l/π) L_lm Y_lm(n): the cosine lobe keeps band 0 whole (Â0/π = 1), band 1 at
// 2/3 and band 2 at 1/4; bands 3 and up are dropped (Â3 = 0, |Â4/π| = 1/24), which is where
// the error lives: nothing for a smooth sky, ringing (even negative light) around a sharp sun.
// Y constants folded with Â_l/π: 0.282095, 0.488603·2/3, 1.092548/4, 0.315392/4, 0.546274/4.
#define SH9_K0 0.2820948
#define SH9_K1 0.3257350
#define SH9_K2 0.2731371
#define SH9_K20 0.0788479
#define SH9_K22 0.1365686

// Takes a unit normal. Negative results (ringing) are clamped: light is never negative.
vec3 irradiance(vec3 n) {
    vec3 e = SH9_K0 * SH_C0
        + SH9_K1 * (SH_C1 * n.y + SH_C2 * n.z + SH_C3 * n.x)
        + SH9_K2 * (SH_C4 * (n.x * n.y) + SH_C5 * (n.y * n.z) + SH_C7 * (n.x * n.z))
        + SH9_K20 * SH_C6 * (3.0 * n.z * n.z - 1.0)
        + SH9_K22 * SH_C8 * (n.x * n.x - n.y * n.y);
    return max(e, vec3(0.0));
}
