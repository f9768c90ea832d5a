/* ---
id = "core.f0_from_ior"
slot = "core"
summary = "Reflectance at normal incidence from an index of refraction"
provides = ["f0FromIor"]
requires = []
sources = ["Fresnel equations at normal incidence", "Filament PBR notes 4.8.3.2"]
formula = 'F_0 = \left( \frac{\eta - 1}{\eta + 1} \right)^2'
--- */
// f0 = ((η − 1) / (η + 1))² for light arriving from air (η = 1) on a medium of index η;
// η = 1.5 (glass, most plastics) gives 0.04.
float f0FromIor(float ior) {
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}
