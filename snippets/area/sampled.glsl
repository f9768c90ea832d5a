/* ---
id = "area.sampled"
slot = "area"
summary = "Area light integrated through the full BRDF by AREA_SAMPLES² stratified samples over the light and as many over the GGX lobe, combined by multiple importance sampling: the reference"
provides = ["areaLight", "areaLobeDensity", "areaLightDensity", "AREA_SPHERE", "AREA_DISC", "AREA_RECT"]
requires = ["Surface", "lightResponse", "PI"]
error_budget = { max_abs = 0.03, rms = 0.002 }
budget_why = "Against the float64 integral (references/area.py, two 256x256 rules joined the same way), 360 lights of every shape, size and tilt: max 0.0147, rms 0.0012, the noise of 2x256 samples, 6x closer than area.representative. The budget is 2x: another GPU rounds the sample directions differently."
params = { AREA_SAMPLES = { type = "int", default = 16, range = [1, 64] } }
sources = ["Veach & Guibas 1995, Optimally combining sampling techniques for Monte Carlo rendering (the balance heuristic)", "Walter et al. 2007, Microfacet models for refraction, eq. 35 (sampling GGX)", "Shirley, Wang & Zimmerman 1996, Monte Carlo techniques for direct lighting calculations (sampling spheres by solid angle, planar lights by area)", "Pharr, Jakob & Humphreys, Physically Based Rendering 4th ed., 12.2 and A.5 (stratified and cone sampling)"]
formula = 'L_o \approx L \sum_{k} \frac{R(\mathbf{l}_k)}{N^2 \left( p_{\text{light}}(\mathbf{l}_k) + p_{\text{lobe}}(\mathbf{l}_k) \right)}, \quad p_{\text{light}} = \frac{1}{\Omega} \text{ (sphere)}, \ \frac{d^2}{A \left| \mathbf{n}_\ell \cdot \mathbf{l} \right|} \text{ (disc, rectangle)}, \quad p_{\text{lobe}} = \frac{D(\mathbf{h})\, (\mathbf{n} \cdot \mathbf{h})}{4\, (\mathbf{v} \cdot \mathbf{h})}'
--- */
// The shapes, as `shape` says at each call: for a sphere `right`'s length is the radius; a
// disc spans `right` and `up` (both its radius long) and shines toward right × up; a rectangle
// spans center ± right ± up (half its sides) and shines toward right × up.
#define AREA_SPHERE 0
#define AREA_DISC 1
#define AREA_RECT 2

// Density per solid angle of a direction L drawn by reflecting V about a GGX half vector.
float areaLobeDensity(Surface s, vec3 L, float a) {
    vec3 H = normalize(s.V + L);
    float NoH = max(dot(s.N, H), 0.0);
    float VoH = dot(s.V, H);
    if (VoH <= 0.0) return 0.0;
    float a2 = a * a;
    float k = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * k * k) * NoH / (4.0 * VoH);
}

// Where the ray from P along L meets the light's lit side: the density per solid angle at
// which the light's own rule draws that direction, or 0 where it misses.
float areaLightDensity(vec3 P, vec3 L, vec3 center, vec3 right, vec3 up, int shape,
                       float omega, float area, vec3 facing) {
    vec3 toCenter = center - P;
    if (shape == AREA_SPHERE) {
        float b = dot(L, toCenter);
        bool hit = b > 0.0 && b * b - dot(toCenter, toCenter) + dot(right, right) >= 0.0;
        return hit ? 1.0 / omega : 0.0;
    }
    float across = dot(L, facing);
    if (across >= 0.0) return 0.0;
    float t = dot(toCenter, facing) / across;
    vec3 q = t * L - toCenter;
    bool inside = shape == AREA_DISC
        ? dot(q, q) <= dot(right, right)
        : abs(dot(q, right)) <= dot(right, right) && abs(dot(q, up)) <= dot(up, up);
    return t > 0.0 && inside ? t * t / (area * -across) : 0.0;
}

// Two stratified rules of AREA_SAMPLES² directions each, combined by the balance heuristic
// (Veach & Guibas 1995): one over the light (a sphere's cone by solid angle, a disc or
// rectangle by area), which carries the diffuse and broad lobes, and one over the GGX lobe
// (half vectors through its inverse CDF), which finds the sharp highlight of a glossy surface
// at a grazing view that samples over the light miss. Every cell's sample is shifted by the
// same offset, which varies from point to point (Cranley-Patterson rotation): the estimate
// is unbiased at every pixel and its error is fine noise, not a grid of highlights.
vec3 areaLight(Surface s, vec3 center, vec3 right, vec3 up, int shape, vec3 radiance) {
    vec3 toCenter = center - s.P;
    float dist2 = max(dot(toCenter, toCenter), 1e-12);
    vec3 Lc = toCenter * inversesqrt(dist2);
    float r2 = dot(right, right);
    // right and up are never parallel, but a light may be small: |right × up| = r² or w·h/4
    vec3 across = cross(right, up);
    vec3 facing = across * inversesqrt(max(dot(across, across), 1e-30));
    if (shape != AREA_SPHERE && dot(facing, s.P - center) <= 0.0) return vec3(0.0);
    // a frame around the way to a sphere's centre, for its cone of directions
    vec3 t1 = normalize(abs(Lc.y) < 0.99 ? cross(Lc, vec3(0.0, 1.0, 0.0)) : cross(Lc, vec3(1.0, 0.0, 0.0)));
    vec3 t2 = cross(Lc, t1);
    float cosMax = sqrt(max(1.0 - r2 / dist2, 0.0));
    float omega = 2.0 * PI * (1.0 - cosMax);
    float area = shape == AREA_RECT ? 4.0 * length(right) * length(up) : PI * r2;
    float a = max(s.a, 1e-3);
    // a frame around the normal, for the lobe's half vectors
    vec3 b1 = normalize(abs(s.N.y) < 0.99 ? cross(s.N, vec3(0.0, 1.0, 0.0)) : cross(s.N, vec3(1.0, 0.0, 0.0)));
    vec3 b2 = cross(s.N, b1);
    vec2 shift = fract(sin(vec2(dot(s.P, vec3(12.9898, 78.233, 37.719)),
                                dot(s.P, vec3(39.3468, 11.135, 83.155)))) * 43758.5453);
    float count = float(AREA_SAMPLES * AREA_SAMPLES);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < AREA_SAMPLES; i++) {
        for (int j = 0; j < AREA_SAMPLES; j++) {
            vec2 u = fract((vec2(i, j) + shift) / float(AREA_SAMPLES));
            // over the light
            vec3 L;
            float density;
            if (shape == AREA_SPHERE) {
                float cosT = 1.0 - u.x * (1.0 - cosMax);
                float sinT = sqrt(max(1.0 - cosT * cosT, 0.0));
                float phi = 2.0 * PI * u.y;
                L = cosT * Lc + sinT * (cos(phi) * t1 + sin(phi) * t2);
                density = 1.0 / omega;
            } else {
                vec2 q = 2.0 * u - 1.0;  // the rectangle's [-1, 1]²
                if (shape == AREA_DISC) q = sqrt(u.x) * vec2(cos(2.0 * PI * u.y), sin(2.0 * PI * u.y));
                vec3 toSample = center + q.x * right + q.y * up - s.P;
                float d2 = max(dot(toSample, toSample), 1e-12);
                L = toSample * inversesqrt(d2);
                density = d2 / (area * max(dot(facing, -L), 1e-8));
            }
            sum += lightResponse(s, L) / (count * (density + areaLobeDensity(s, L, a)));
            // over the lobe
            float cos2 = (1.0 - u.x) / (1.0 + (a * a - 1.0) * u.x);
            float sinH = sqrt(max(1.0 - cos2, 0.0));
            float phi = 2.0 * PI * u.y;
            vec3 H = sqrt(cos2) * s.N + sinH * (cos(phi) * b1 + sin(phi) * b2);
            L = reflect(-s.V, H);
            density = areaLightDensity(s.P, L, center, right, up, shape, omega, area, facing);
            if (density > 0.0 && dot(s.N, L) > 0.0) {
                sum += lightResponse(s, L) / (count * (density + areaLobeDensity(s, L, a)));
            }
        }
    }
    return sum * radiance;
}
