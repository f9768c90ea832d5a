/* ---
id = "V.cook_torrance"
slot = "V"
summary = "Cook-Torrance's V-groove geometry term, min(1, 2NoH NoV/VoH, 2NoH NoL/VoH) / (4 NoL NoV)"
provides = ["visibility", "MIN_CT_COS"]
requires = ["Dots"]
domain = { NoV = [0.001, 1], NoL = [0.001, 1], NoH = [0, 1], VoH = [0.001, 1] }
reference = "V_cook_torrance"
error_budget = { max_abs = 0.05, max_rel = 1e-5 }
budget_why = "Float32 rounding only: measured 9.1e-8 relative and 0.0075 absolute where V reaches 2.5e5 (all cosines 0.001) on llvmpipe; the budget leaves over 100x relative and about 7x absolute."
sources = ["Cook & Torrance 1982, eq. 7", "Blinn 1977"]
formula = 'V = \min\left( \frac{1}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})},\ \frac{\mathbf{n} \cdot \mathbf{h}}{2 (\mathbf{v} \cdot \mathbf{h})(\mathbf{n} \cdot \mathbf{l})},\ \frac{\mathbf{n} \cdot \mathbf{h}}{2 (\mathbf{v} \cdot \mathbf{h})(\mathbf{n} \cdot \mathbf{v})} \right) = \frac{G}{4 (\mathbf{n} \cdot \mathbf{l})(\mathbf{n} \cdot \mathbf{v})}'
--- */
// Smallest cosine in a denominator: NoL, NoV and VoH can each be 0 at grazing.
#define MIN_CT_COS 1e-5

// G = min(1, 2 NoH NoV / VoH, 2 NoH NoL / VoH) (Cook & Torrance 1982), divided by 4 NoL NoV
// term by term, V = min(1/(4 NoL NoV), NoH/(2 VoH NoL), NoH/(2 VoH NoV)), so that the 0/0 of
// NoL → 0 becomes its finite limit. It does not depend on the roughness a.
float visibility(Dots d, float a) {
    float NoL = max(clamp(d.NoL, 0.0, 1.0), MIN_CT_COS);
    float NoV = max(clamp(d.NoV, 0.0, 1.0), MIN_CT_COS);
    float NoH = clamp(d.NoH, 0.0, 1.0);
    float VoH = max(clamp(d.VoH, 0.0, 1.0), MIN_CT_COS);
    float h = 0.5 * NoH / VoH;
    return min(0.25 / (NoL * NoV), min(h / NoL, h / NoV));
}
