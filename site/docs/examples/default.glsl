// glint 0.1.0 - scene 'default', tier balanced, target shadertoy
// Paste into the Image tab of https://www.shadertoy.com/new as it is.
// Snippets, in order:
//   core.constants              Mathematical constants shared by every snippet
//   core.surface                Shading point and the dot products a BRDF term needs, computed once
//   sdf.plane                   Signed distance to an infinite plane with unit normal n, offset h from the origin
//   sdf.sphere                  Signed distance to a sphere centred at the origin
//   pattern.checker             Checkerboard on the xz plane: 0 or 1 per unit cell
//   light.back                  Back (rim) fill from a horizontal direction, wrapped half-Lambert, occluded by AO
//   light.sky                   Sky fill: the cheap hemisphere integral 0.5 + 0.5·N.y, diffuse only, occluded by AO
//   D.ggx                       GGX / Trowbridge-Reitz normal distribution
//   F.schlick                   Schlick's Fresnel approximation with pow
//   V.smith_ggx_correlated      Height-correlated Smith visibility for GGX, G / (4 NoL NoV), exact form
//   diffuse.lambert             Lambert: albedo / π times N·L (energy conserving)
//   specular.cook_torrance      Cook-Torrance microfacet lobe assembled from the chosen D, F and V
//   light.response              What a surface reflects toward the eye per unit radiance arriving from L: diffuse and specular lobes
//   light.directional           Directional light: the surface's response times radiance and visibility
//   specocc.power               Specular occlusion from AO: clamp((NoV + ao)^a − 1 + ao)
//   env.gradient                Environment as a vertical gradient from ENV_BOTTOM (down) to ENV_TOP (up)
//   ibl.env_brdf_approx         Environment along the mirror direction times Karis's analytic split-sum fit f0·A + B, with specular occlusion
//   camera.orbit                Pinhole camera orbiting CAMERA_TARGET with iTime, or where a mouse drag puts it, looking at it
//   background.gradient_sun     The environment gradient plus a glow and a disc around the sun
//   tonemap.reinhard            Reinhard tone map, c / (c + 1) per channel
//   output.gamma22              Display encoding with a pure 2.2 gamma
//   ao.sdf5                     SDF ambient occlusion, 5 taps along the normal
//   shadow.soft_centered        Soft shadow with the penumbra centred on the hard shadow's edge: signed k·h/t, marched through occluders
//   normal.central_differences  SDF normal by central differences, 6 taps
//   raymarch.cone               Sphere tracing that stops once the scene is within a pixel's cone, then refines the hit by one secant step

// source: <generated>:1
// Scene constants (light directions point toward the light).
#define SUN_DIR normalize(vec3(0.6, 0.8, -0.5))
#define SUN_COLOR (vec3(1.0, 0.95, 0.85) * 2.0)
#define SKY_COLOR (vec3(0.2, 0.5, 1.0) * 0.4)
#define BACK_DIR normalize(vec3(-SUN_DIR.x, 0.0, -SUN_DIR.z))
#define BACK_COLOR vec3(0.15, 0.1, 0.08)
// Parameters of the snippets below.
#define ENV_TOP vec3(0.5, 0.7, 1.0)
#define ENV_BOTTOM vec3(0.8, 0.85, 0.9)
#define CAMERA_RADIUS 3.0
#define CAMERA_HEIGHT 1.5
#define CAMERA_SPEED 0.3
#define CAMERA_TARGET vec3(0.0, 0.0, 0.0)
#define CAMERA_FOCAL 1.5
#define AO_STRENGTH 3.0
#define SHADOW_STEPS 32
#define SHADOW_K 8.0
#define SHADOW_MIN_STEP 0.05
#define SHADOW_MAX_STEP 2.0
#define NORMAL_EPS 0.001
#define MARCH_STEPS 64
#define MARCH_EPSILON 0.001
#define MARCH_PIXEL 0.002
#define MARCH_FAR 50.0

// source: snippets/core/constants.glsl:10
#define PI 3.14159265359

// source: snippets/core/surface.glsl:10
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
// Dielectric reflectance at normal incidence (IOR 1.5).
#define DIELECTRIC_F0 0.04

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

// source: snippets/sdf/plane.glsl:10
float sdPlane(vec3 p, vec3 n, float h) {
    return dot(p, n) + h;
}

// source: snippets/sdf/sphere.glsl:10
float sdSphere(vec3 p, float radius) {
    return length(p) - radius;
}

// source: snippets/pattern/checker.glsl:10
float checker(vec3 p) {
    return mod(floor(p.x) + floor(p.z), 2.0);
}

// source: snippets/light/back.glsl:10
vec3 backLight(Surface s, vec3 dir, vec3 color, float occlusion) {
    float wrapped = clamp(dot(s.N, dir) * 0.5 + 0.5, 0.0, 1.0);
    return s.diffuseColor * color * wrapped * occlusion;
}

// source: snippets/light/sky.glsl:10
vec3 skyLight(Surface s, vec3 color, float occlusion) {
    float hemisphere = 0.5 + 0.5 * s.N.y;
    return s.diffuseColor * color * hemisphere * occlusion;
}

// source: snippets/D/ggx.glsl:13
// Floor of (NoH² (a² − 1) + 1): it is 0 at a = 0, NoH = 1, where D is a Dirac spike (0/0).
#define MIN_GGX_DENOM 1e-15

// D(h) = a² / (π ((n·h)² (a² − 1) + 1)²). Takes a = roughness², never roughness.
// In float32 the denominator loses digits by cancellation next to NoH = 1 at low roughness
// (about 3% at a = 0.002); D.ggx_mediump avoids it.
float distribution(float NoH, float a) {
    NoH = clamp(NoH, 0.0, 1.0);
    float a2 = a * a;
    float d = max(NoH * NoH * (a2 - 1.0) + 1.0, MIN_GGX_DENOM);
    return a2 / (PI * d * d);
}

// source: snippets/F/schlick.glsl:13
// F = f0 + (1 − f0)(1 − cosθ)⁵ (Schlick 1994), an approximation of the exact dielectric
// Fresnel: within 0.036 of it at f0 = 0.04, 0.10 at f0 = 0.2 (the budget's domain is
// dielectrics, water to diamond; towards f0 = 1 the exact dielectric has a Brewster dip that
// Schlick lacks). cosTheta is V·H for a light, N·V for the environment; never N·L.
// 1 − cosTheta is clamped: pow of a negative base is undefined in GLSL.
vec3 fresnel(vec3 f0, float cosTheta) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// source: snippets/V/smith_ggx_correlated.glsl:13
// Smallest denominator: both terms vanish when NoL = NoV = 0.
#define MIN_VIS_DENOM 1e-5

// V = G2 / (4 NoL NoV) with G2 = 1 / (1 + Λ(v) + Λ(l)), Λ of GGX, multiplied out so that it is
// finite at NoL = 0 (Heitz 2014, Filament). The cosines are clamped to [0, 1].
float visibility(Dots d, float a) {
    float NoL = clamp(d.NoL, 0.0, 1.0);
    float NoV = clamp(d.NoV, 0.0, 1.0);
    float a2 = a * a;
    float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, MIN_VIS_DENOM);
}

// source: snippets/diffuse/lambert.glsl:13
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * (d.NoL / PI);
}

// source: snippets/specular/cook_torrance.glsl:10
// V already holds G / (4 NoL NoV), so the lobe is a plain product, times its cosine N·L.
vec3 specular(Surface s, Dots d, vec3 F) {
    return distribution(d.NoH, s.a) * visibility(d, s.a) * F * d.NoL;
}

// source: snippets/light/response.glsl:10
// The diffuse share is what the Fresnel term does not reflect (energy split). Each lobe
// carries its own cosine factor, so a wrapped diffuse model can light past the terminator.
vec3 lightResponse(Surface s, vec3 L) {
    Dots d = lightDots(s, L);
    vec3 F = fresnel(s.f0, d.VoH);
    return (1.0 - F) * diffuse(s, d) + specular(s, d, F);
}

// source: snippets/light/directional.glsl:10
// `visibility` is per channel, so a shadow can tint its penumbra (see the scene's `penumbra`).
vec3 directionalLight(Surface s, vec3 L, vec3 radiance, vec3 visibility) {
    return lightResponse(s, L) * radiance * visibility;
}

// source: snippets/specocc/power.glsl:11
float specularOcclusion(float NoV, float ao, float a) {
    return clamp(pow(NoV + ao, a) - 1.0 + ao, 0.0, 1.0);
}

// source: snippets/env/gradient.glsl:11
vec3 environment(vec3 dir) {
    return mix(ENV_BOTTOM, ENV_TOP, clamp(dir.y * 0.5 + 0.5, 0.0, 1.0));
}

// source: snippets/ibl/env_brdf_approx.glsl:15
// The split sum (Karis 2013) factors specular environment light into the environment seen
// around the mirror direction times the BRDF's directional albedo, f0·A + B. Here A and B
// come from Karis's analytic fit instead of a lookup table, and the environment is sampled
// once along R without prefiltering (fine for a smooth sky, too sharp for a rough mirror of
// a detailed one).
//
// Error of (A, B) against the float64 split sum with GGX, height-correlated Smith and Schlick
// (compiler/verify/references/environment.dfg_split_sum), roughness and NoV in [0, 1]: see
// tests/test_environment_light.py. The fit was made for a table with a different masking
// term, so it is close at normal incidence and far off at grazing angles on rough surfaces,
// where height-correlated Smith keeps much more energy: f0·A + B off by up to 0.55 (metals,
// NoV → 0, roughness 1), 0.08 for f0 = 0.04. The GPU gives the same (A, B) as the float32
// evaluator to 2e-7, NoV just outside [0, 1] included. A dips to −0.044 for a grazing mirror
// (f0·A + B up to 1.042 there) and B to −0.0024 at roughness 1: f0·A + B stays ≥ 0 for
// f0 ≥ 0.04, not quite for f0 = 0.

// (A, B) such that the directional albedo is f0·A + B. Perceptual roughness, as Karis fits it.
vec2 envBRDFApprox(float NoV, float roughness) {
    vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float grazing = min(r.x * r.x, exp2(-9.28 * NoV)) * r.x + r.y;
    return vec2(-1.04, 1.04) * grazing + r.zw;
}

vec3 environmentLight(Surface s, float ao) {
    vec3 R = reflect(-s.V, s.N);
    vec2 AB = envBRDFApprox(s.NoV, s.roughness);
    float occlusion = specularOcclusion(s.NoV, ao, s.a);
    return (s.f0 * AB.x + AB.y) * environment(R) * occlusion;
}

// source: snippets/camera/orbit.glsl:11
// Screen coordinates span [-1, 1] vertically; CAMERA_FOCAL is the distance to that screen.
// A mouse drag orbits: ShaderToy keeps iMouse.xy where the button was last held and gives 0
// before any drag, so a render (no mouse) follows iTime and the picture does not change.
void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    float angle = iTime * CAMERA_SPEED;
    float height = CAMERA_HEIGHT;
    if (iMouse.x > 0.0 || iMouse.y > 0.0) {
        angle = 6.28318531 * iMouse.x / iResolution.x;
        height = 2.0 * CAMERA_HEIGHT * iMouse.y / iResolution.y;
    }
    ro = CAMERA_TARGET + vec3(CAMERA_RADIUS * cos(angle), height, CAMERA_RADIUS * sin(angle));
    vec3 ww = normalize(CAMERA_TARGET - ro);
    vec3 uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
    vec3 vv = cross(uu, ww);
    rd = normalize(uv.x * uu + uv.y * vv + CAMERA_FOCAL * ww);
}

// source: snippets/background/gradient_sun.glsl:10
vec3 background(vec3 rd) {
    float sun = clamp(dot(rd, SUN_DIR), 0.0, 1.0);
    vec3 col = environment(rd);
    col += SUN_COLOR * 0.3 * pow(sun, 8.0);
    col += SUN_COLOR * pow(sun, 256.0);
    return col;
}

// source: snippets/tonemap/reinhard.glsl:10
vec3 tonemap(vec3 color) {
    return color / (color + vec3(1.0));
}

// source: snippets/output/gamma22.glsl:10
// max() keeps pow defined: its base must not be negative.
vec3 outputTransfer(vec3 color) {
    return pow(max(color, 0.0), vec3(1.0 / 2.2));
}

// source: <generated>:1
// The scene's signed distance: the union of its objects.
float map(vec3 p) {
    float d = sdSphere(p, 1.0);
    d = min(d, sdPlane(p, vec3(0.0, 1.0, 0.0), 1.0));
    return d;
}

// source: snippets/ao/sdf5.glsl:15
// Compares the distance field at growing heights h along n with h itself: the shortfall is
// how much nearby geometry closes in. Nearer taps weigh more.
float ambientOcclusion(vec3 p, vec3 n) {
    float occ = 0.0;
    float weight = 1.0;
    for (int i = 0; i < 5; i++) {
        float h = 0.01 + 0.12 * float(i) / 4.0;
        occ += (h - map(p + h * n)) * weight;
        weight *= 0.95;
    }
    return clamp(1.0 - AO_STRENGTH * occ, 0.0, 1.0);
}

// source: snippets/shadow/soft_centered.glsl:17
// shadow.soft draws the whole penumbra outside the hard shadow: a ray that grazes an occluder
// gives 0 where a disc light is half hidden. Here the gap h/t is signed. The march goes on into
// an occluder, where the distance field is negative, so x = k·h/t, the ray's angular distance
// to the occluder's edge in units of the light's radius atan(1/k), runs from +1 (the disc
// clears the edge) through 0 (the disc's centre on the edge) to −1 (the disc hidden). The
// visible fraction of a disc cut by a straight edge at x, 1/2 + (x·√(1 − x²) + asin x)/π, is
// fitted by the cubic 0.25·(1 + x)²·(2 − x) (within 0.04; equal at x = −1, 0 and 1).
//
// Steps are |h|, the radius of a ball free of surfaces around the sample, inside an occluder
// as outside, and at least SHADOW_MIN_STEP so the march crosses an edge it runs along; the
// march ends once the light is hidden (x ≤ −1) or past tmax. At most SHADOW_MAX_STEP, a
// bound on how far past an occluder's closest approach a step may land.
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float res = 1.0;
    float t = max(tmin, 1e-3);  // h/t has no value at t = 0
    for (int i = 0; i < SHADOW_STEPS; i++) {
        float h = map(ro + rd * t);
        res = min(res, SHADOW_K * h / t);
        t += clamp(abs(h), SHADOW_MIN_STEP, SHADOW_MAX_STEP);
        if (res <= -1.0 || t > tmax) break;
    }
    res = max(res, -1.0);
    return 0.25 * (1.0 + res) * (1.0 + res) * (2.0 - res);
}

// source: snippets/normal/central_differences.glsl:13
vec3 calcNormal(vec3 p) {
    vec2 e = vec2(NORMAL_EPS, 0.0);
    return normalize(vec3(
        map(p + e.xyy) - map(p - e.xyy),
        map(p + e.yxy) - map(p - e.yxy),
        map(p + e.yyx) - map(p - e.yyx)
    ));
}

// source: snippets/raymarch/cone.glsl:11
// A pixel sees a cone about 2 / (iResolution.y · focal) radians wide. Once the scene is nearer
// the ray than MARCH_PIXEL · t (or MARCH_EPSILON, near the eye) the march stops: more steps
// would not change which surface the pixel shows. A grazing ray along a plane shrinks its
// distance only by a factor 1 − sin θ per step, so the fixed tolerance of
// raymarch.sphere_tracing spends most of its steps there (or all of them, and misses).
// MARCH_PIXEL = 0.002 is about half a pixel at 640 × 360 with a focal length of 1.5. Half the
// steps of raymarch.sphere_tracing: on the default scene at 480 × 270, 64 steps miss 38 pixels
// that 128 steps of sphere tracing hit (0.03%) and hit 1014 that it misses (0.8%: far ground
// near the horizon, where sphere tracing runs out of steps).
//
// Stopping early leaves the hit short of the surface, along a grazing ray by d / sin θ, about
// a pixel's footprint: texture edges would move. Along a straight stretch the distance falls
// linearly with t, so the last two samples (d_prev one plain step of d_prev behind, d here)
// say where it reaches 0: d · d_prev / (d_prev − d) further on, exact for a plane. One more
// map() checks the secant point and it is kept only where it lies nearer the surface.
float raymarch(vec3 ro, vec3 rd) {
    float t = 0.0;
    float d = MARCH_FAR;
    float dPrev = 0.0;  // distance at the previous sample, which lies dPrev behind t
    bool hit = false;
    for (int i = 0; i < MARCH_STEPS; i++) {
        d = map(ro + rd * t);
        if (d < max(MARCH_EPSILON, MARCH_PIXEL * t)) {
            hit = true;
            break;
        }
        dPrev = d;
        t += d;
        if (t > MARCH_FAR) break;
    }
    if (!hit) return -1.0;
    // Refined outside the loop: a branch taken by some pixels of a SIMD group costs all of them.
    float ahead = d < dPrev ? d * dPrev / (dPrev - d) : 0.0;
    float dAhead = map(ro + rd * (t + ahead));
    return abs(dAhead) < abs(d) ? t + ahead : t;
}

// source: <generated>:1
// Index of the material of the object nearest to p.
int materialAt(vec3 p) {
    float best = sdSphere(p, 1.0);
    int id = 0;
    float d1 = sdPlane(p, vec3(0.0, 1.0, 0.0), 1.0);
    if (d1 < best) { best = d1; id = 1; }
    return id;
}

// source: <generated>:1
// Light arriving at the eye from a surface point.
vec3 shade(Surface s) {
    float occlusion = ambientOcclusion(s.P, s.N);
    vec3 color = vec3(0.0);
    color += directionalLight(s, SUN_DIR, SUN_COLOR, vec3(shadow(s.P, SUN_DIR, 0.02, 5.0)));
    color += skyLight(s, SKY_COLOR, occlusion);
    color += backLight(s, BACK_DIR, BACK_COLOR, occlusion);
    color += environmentLight(s, occlusion);
    return color;
}

// source: <generated>:1
// The material at a hit point.
Surface surfaceAt(vec3 P, vec3 N, vec3 V) {
    int id = materialAt(P);
    if (id == 1) {
        return makeSurface(P, N, V, mix(vec3(0.3, 0.3, 0.3), vec3(0.6, 0.6, 0.6), checker(P)), 0.8);
    }
    return makeSurface(P, N, V, vec3(0.8, 0.2, 0.2), 0.35);
}

// source: <generated>:1
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 ro;
    vec3 rd;
    cameraRay(fragCoord, ro, rd);
    vec3 color = background(rd);
    float t = raymarch(ro, rd);
    if (t > 0.0) {
        vec3 P = ro + t * rd;
        color = shade(surfaceAt(P, calcNormal(P), -rd));
    }
    color = outputTransfer(tonemap(color));
    fragColor = vec4(color, 1.0);
}
