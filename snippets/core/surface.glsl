/* ---
id = "core.surface"
slot = "core"
summary = "Shading point and the dot products a BRDF term needs, computed once"
provides = ["Surface", "Dots", "makeSurface", "lightDots", "MIN_NOV"]
requires = []
# Dielectric reflectance at normal incidence: 0.04 is IOR 1.5 (glass, most plastics); water
# 0.02, gemstones up to about 0.17 (diamond).
params = { DIELECTRIC_F0 = { type = "float", default = 0.04, range = [0.0, 0.17] } }
sources = ["lighting-model skill, steps 1 and 8", "Filament PBR notes, 4.4 (parameterization)"]
formula = '\mathbf{h} = \frac{\mathbf{v} + \mathbf{l}}{\|\mathbf{v} + \mathbf{l}\|}, \quad \alpha = \text{roughness}^2, \quad \mathbf{n} \cdot \mathbf{v} \to \max(\mathbf{n} \cdot \mathbf{v}, 10^{-4}), \quad \mathbf{n} \cdot \mathbf{l},\ \mathbf{n} \cdot \mathbf{h},\ \mathbf{v} \cdot \mathbf{h} \to \max(\cdot, 0), \quad F_0 = \text{DIELECTRIC\_F0} = 0.04'
--- */
// Everything about the point being shaded. Vectors point away from the surface.
struct Surface {
    vec3 P;             // position
    vec3 N;             // unit normal
    vec3 V;             // unit vector toward the eye
    vec3 diffuseColor;  // albedo, with the diffuse of metals removed
    vec3 f0;            // specular reflectance at normal incidence
    float roughness;    // perceptual roughness
    float a;            // roughness squared: the one place it is squared
    float NoV;          // clamped away from 0 so that visibility terms stay finite
    float diffuseRoughness;  // Oren-Nayar's σ in radians; makeSurface sets the roughness
};

// The dot products of one light direction, clamped to where the BRDF is defined, and N·L
// before clamping, for the models that wrap light past the terminator (half-Lambert, toon).
struct Dots {
    float NoL;
    float NoV;
    float NoH;
    float VoH;
    float LoV;
    float NoLsigned;
};

// Smallest NoV: at exactly 0 the Smith visibility divides 0 by 0 on silhouettes.
#define MIN_NOV 1e-4

// A dielectric; the core.metallic snippet turns it toward a metal where a material is one.
Surface makeSurface(vec3 P, vec3 N, vec3 V, vec3 albedo, float roughness) {
    Surface s;
    s.P = P;
    s.N = N;
    s.V = V;
    s.diffuseColor = albedo;
    s.f0 = vec3(DIELECTRIC_F0);
    s.roughness = roughness;
    s.a = roughness * roughness;
    s.NoV = max(dot(N, V), MIN_NOV);
    // A material without its own diffuse roughness is as rough for diffuse as for specular.
    s.diffuseRoughness = roughness;
    return s;
}

Dots lightDots(Surface s, vec3 L) {
    // With the light straight behind the surface as seen (L = −V) the half vector is
    // undefined and normalize(0) is NaN; a zero H gives N·H = V·H = 0 instead.
    vec3 sum = s.V + L;
    vec3 H = sum * inversesqrt(max(dot(sum, sum), 1e-12));
    Dots d;
    d.NoLsigned = dot(s.N, L);
    d.NoL = max(d.NoLsigned, 0.0);
    d.NoV = s.NoV;
    d.NoH = max(dot(s.N, H), 0.0);
    d.VoH = max(dot(s.V, H), 0.0);
    d.LoV = dot(L, s.V);
    return d;
}
