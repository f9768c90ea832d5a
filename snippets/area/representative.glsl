/* ---
id = "area.representative"
slot = "area"
summary = "Area light by one representative direction: the point of the light nearest the mirror ray for the specular (roughness widened by the light's size), an analytic form factor for the diffuse"
provides = ["areaLight", "areaCapIrradiance", "areaRectIrradiance", "AREA_SPHERE", "AREA_DISC", "AREA_RECT"]
requires = ["Surface", "Dots", "lightDots", "fresnel", "specular", "PI"]
error_budget = { max_abs = 0.12, rms = 0.01 }
budget_why = "Against the float64 integral (references/area.py), 360 lights of every shape, size and tilt: max 0.092 (a glossy surface at a grazing view under a large sphere), rms 0.0073; the budget is about 1.3x. AREA_WIDEN = 1 was chosen by it: 0.5 gives max 1.24, 0.75 gives 0.21, 2 gives 0.32."
params = { AREA_WIDEN = { type = "float", default = 1.0, range = [0.0, 2.0] } }
sources = ["Karis 2013, Real Shading in Unreal Engine 4, 'Area lights' (representative point, sphere normalization)", "Lagarde & de Rousiers 2014, Moving Frostbite to PBR, 4.7 (sphere and disc form factors with the horizon; listing 7)", "Lambert 1760 / Baum et al. 1989: the form factor of a polygon from its edges"]
formula = 'L_o = L \left[ (1 - F)\,\frac{\rho}{\pi}\, E_\Omega(\mathbf{n}) + f_s^{\alpha^{\prime}}(\mathbf{l}_r)\,(\mathbf{n}\cdot\mathbf{l}_r)\,\Omega \right], \quad \alpha^{\prime} = \min(\alpha + w\, r / d, 1)'
--- */
// The shapes, as `shape` says at each call: for a sphere `right`'s length is the radius; a
// disc spans `right` and `up` (both its radius long) and shines toward right × up; a rectangle
// spans center ± right ± up (half its sides) and shines toward right × up.
#define AREA_SPHERE 0
#define AREA_DISC 1
#define AREA_RECT 2

// Irradiance per unit radiance from a sphere or a disc facing the point, of angular radius σ
// (sin²σ given), its centre at cos θ from the normal: π sin²σ cos θ while it is all above the
// horizon; the exact integral of the cap cut by the horizon when part of it sinks below.
float areaCapIrradiance(float cosTheta, float sin2Sigma) {
    float sin2Theta = max(1.0 - cosTheta * cosTheta, 1e-8);
    if (cosTheta * cosTheta > sin2Sigma) return PI * sin2Sigma * max(cosTheta, 0.0);
    float sinTheta = sqrt(sin2Theta);
    float x = sqrt(max(1.0 / max(sin2Sigma, 1e-12) - 1.0, 1e-8));
    float y = clamp(-x * cosTheta / sinTheta, -1.0, 1.0);
    float w = sinTheta * sqrt(1.0 - y * y);
    return max((cosTheta * acos(y) - x * w) * sin2Sigma + atan(w / x), 0.0);
}

// Irradiance per unit radiance from the rectangle whose corners are p0..p3 seen from P with
// normal N: Lambert's sum over the edges of the angle each spans times the cosine of its
// plane's normal with N. Exact while the rectangle is above the horizon; past it the part
// below adds a negative share, which the clamp only bounds.
float areaRectIrradiance(vec3 P, vec3 N, vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
    vec3 v0 = normalize(p0 - P);
    vec3 v1 = normalize(p1 - P);
    vec3 v2 = normalize(p2 - P);
    vec3 v3 = normalize(p3 - P);
    float sum = 0.0;
    vec3 e;
    e = cross(v0, v1); sum += acos(clamp(dot(v0, v1), -1.0, 1.0)) * dot(N, e) * inversesqrt(max(dot(e, e), 1e-12));
    e = cross(v1, v2); sum += acos(clamp(dot(v1, v2), -1.0, 1.0)) * dot(N, e) * inversesqrt(max(dot(e, e), 1e-12));
    e = cross(v2, v3); sum += acos(clamp(dot(v2, v3), -1.0, 1.0)) * dot(N, e) * inversesqrt(max(dot(e, e), 1e-12));
    e = cross(v3, v0); sum += acos(clamp(dot(v3, v0), -1.0, 1.0)) * dot(N, e) * inversesqrt(max(dot(e, e), 1e-12));
    return max(0.5 * sum, 0.0);
}

vec3 areaLight(Surface s, vec3 center, vec3 right, vec3 up, int shape, vec3 radiance) {
    vec3 toCenter = center - s.P;
    float dist2 = max(dot(toCenter, toCenter), 1e-12);
    float dist = sqrt(dist2);
    vec3 Lc = toCenter / dist;
    float r2 = dot(right, right);
    // right and up are never parallel, but a light may be small: |right × up| = r² or w·h/4
    vec3 across = cross(right, up);
    vec3 facing = shape == AREA_SPHERE ? -Lc : across * inversesqrt(max(dot(across, across), 1e-30));
    float lit = max(dot(facing, -Lc), 0.0);  // how squarely its lit face looks at the point
    if (shape != AREA_SPHERE && dot(facing, s.P - center) <= 0.0) return vec3(0.0);

    // Diffuse: the light's irradiance here, as a form factor.
    float E;
    if (shape == AREA_RECT) {
        E = areaRectIrradiance(s.P, s.N, center - right - up, center - right + up,
                               center + right + up, center + right - up);
    } else if (shape == AREA_DISC) {
        E = lit * areaCapIrradiance(dot(s.N, Lc), r2 / (r2 + dist2));
    } else {
        E = areaCapIrradiance(dot(s.N, Lc), min(r2 / dist2, 1.0));
    }

    // Specular: the point of the light nearest the mirror ray (Karis 2013), lit as a point
    // light of the same solid angle. For a disc or rectangle: where the mirror ray meets its
    // plane (or, pointing away, the point of the ray at the centre's distance), clamped to it.
    vec3 R = reflect(-s.V, s.N);
    vec3 toPoint;
    if (shape == AREA_SPHERE) {
        vec3 centerToRay = dot(toCenter, R) * R - toCenter;
        toPoint = toCenter + centerToRay * min(sqrt(r2) * inversesqrt(max(dot(centerToRay, centerToRay), 1e-12)), 1.0);
    } else {
        float across = dot(R, facing);
        float along = across < -1e-4 ? dot(toCenter, facing) / across : dot(toCenter, R);
        vec3 offset = s.P + R * max(along, 0.0) - center;
        offset -= facing * dot(offset, facing);
        if (shape == AREA_DISC) {
            offset *= min(sqrt(r2) * inversesqrt(max(dot(offset, offset), 1e-12)), 1.0);
        } else {
            vec3 ru = normalize(right);
            vec3 uu = normalize(up);
            offset = ru * clamp(dot(offset, ru), -length(right), length(right))
                   + uu * clamp(dot(offset, uu), -length(up), length(up));
        }
        toPoint = center + offset - s.P;
    }
    vec3 L = normalize(toPoint);
    // Solid angle of the light: exact for the sphere's cap; the disc and rectangle as a disc
    // of their area, foreshortened.
    float area = shape == AREA_RECT ? 4.0 * length(right) * length(up) : PI * r2;
    float omega = shape == AREA_SPHERE
        ? 2.0 * PI * (1.0 - sqrt(max(1.0 - r2 / dist2, 0.0)))
        : area * lit / (dist2 + area / PI);
    // One direction stands for the whole light: the lobe is widened by the light's angular
    // size (Karis's normalisation: its peak is then that of the original lobe times (α/α')²).
    Surface wide = s;
    float size = sqrt(area / PI) / dist;
    wide.a = min(s.a + AREA_WIDEN * size, 1.0);
    Dots d = lightDots(wide, L);
    vec3 F = fresnel(s.f0, d.VoH);
    vec3 diffuseTerm = (1.0 - fresnel(s.f0, max(dot(s.V, normalize(s.V + Lc)), 0.0))) * s.diffuseColor * (E / PI);
    return (diffuseTerm + specular(wide, d, F) * omega) * radiance;
}
