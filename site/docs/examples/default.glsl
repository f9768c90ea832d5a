// glint 0.1.0 - scene 'default', tier balanced, target shadertoy
// Paste into the Image tab of https://www.shadertoy.com/new as it is.
// Snippets, in order:
//   core.constants           Mathematical constants shared by every snippet
//   core.surface             Shading point and the dot products a BRDF term needs, computed once
//   sdf.plane                Signed distance to an infinite plane with unit normal n, offset h from the origin
//   sdf.sphere               Signed distance to a sphere centred at the origin
//   trace.plane              A ray against the half-space below a plane (unit normal n, offset h): the first hit, and the ray's angular clearance from it
//   trace.sphere             A ray against a sphere centred at the origin: the first hit, and the ray's angular clearance from it
//   pattern.checker          Checkerboard on the xz plane: 0 or 1 per unit cell
//   light.back               Back (rim) fill from a horizontal direction, wrapped half-Lambert, occluded by AO
//   light.sky                Sky fill: the cheap hemisphere integral 0.5 + 0.5·N.y, diffuse only, occluded by AO
//   D.ggx                    GGX / Trowbridge-Reitz normal distribution
//   F.schlick                Schlick's Fresnel approximation with pow
//   V.smith_ggx_correlated   Height-correlated Smith visibility for GGX, G / (4 NoL NoV), exact form
//   diffuse.lambert          Lambert: albedo / π times N·L (energy conserving)
//   specular.cook_torrance   Cook-Torrance microfacet lobe assembled from the chosen D, F and V
//   light.response           What a surface reflects toward the eye per unit radiance arriving from L: diffuse and specular lobes
//   light.directional        Directional light: the surface's response times radiance and visibility
//   specocc.power            Specular occlusion from AO: clamp((NoV + ao)^a − 1 + ao)
//   env.gradient             Environment as a vertical gradient from ENV_BOTTOM (down) to ENV_TOP (up)
//   ibl.env_brdf_approx      Environment along the mirror direction times Karis's analytic split-sum fit f0·A + B, with specular occlusion
//   camera.orbit             Pinhole camera orbiting CAMERA_TARGET with iTime, or where a mouse drag puts it, looking at it
//   background.gradient_sun  The environment gradient plus a glow and a disc around the sun
//   tonemap.reinhard         Reinhard tone map, c / (c + 1) per channel
//   output.gamma22           Display encoding with a pure 2.2 gamma
//   ao.sdf5                  SDF ambient occlusion, 5 taps along the normal
//   shadow.analytic          Soft shadow from the exact angular clearance of the ray from each analytic primitive: no march
//   normal.analytic          The exact normal of the nearest analytic primitive (every object a sphere, box or plane), no map() taps
//   raymarch.analytic        No march: the nearest of the scene's closed-form ray hits (every object an analytic primitive)

// source: <generated>:1
// Scene constants (light directions point toward the light).
#define SUN_DIR normalize(vec3(0.6, 0.8, -0.5))
#define SUN_INTENSITY 2.0
#define SUN_COLOR (vec3(1.0, 0.95, 0.85) * SUN_INTENSITY)
#define SKY_INTENSITY 0.4
#define SKY_COLOR (vec3(0.2, 0.5, 1.0) * SKY_INTENSITY)
#define BACK_DIR normalize(vec3(-SUN_DIR.x, 0.0, -SUN_DIR.z))
#define BACK_INTENSITY 1.0
#define BACK_COLOR (vec3(0.15, 0.1, 0.08) * BACK_INTENSITY)
#define MAT_RED_ALBEDO vec3(0.8, 0.2, 0.2)
#define MAT_RED_ROUGHNESS 0.35
#define MAT_GROUND_ALBEDO vec3(0.3, 0.3, 0.3)
#define MAT_GROUND_ROUGHNESS 0.8
#define EXPOSURE 1.0
// Parameters of the snippets below.
#define DIELECTRIC_F0 0.04
#define ENV_TOP vec3(0.5, 0.7, 1.0)
#define ENV_BOTTOM vec3(0.8, 0.85, 0.9)
#define CAMERA_RADIUS 3.0
#define CAMERA_HEIGHT 1.5
#define CAMERA_SPEED 0.3
#define CAMERA_TARGET vec3(0.0, 0.0, 0.0)
#define CAMERA_FOCAL 1.5
#define CAMERA_ROLL 0.0
#define CAMERA_START 0.0
#define AO_STRENGTH 3.0
#define SHADOW_K 8.0
#define MARCH_FAR 50.0

// source: snippets/core/constants.glsl:10
#define PI 3.14159265359

// source: snippets/core/surface.glsl:13
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

// source: snippets/sdf/plane.glsl:10
float sdPlane(vec3 p, vec3 n, float h) {
    return dot(p, n) + h;
}

// source: snippets/sdf/sphere.glsl:10
float sdSphere(vec3 p, float radius) {
    return length(p) - radius;
}

// source: snippets/trace/plane.glsl:10
// The solid is the half-space where dot(p, n) + h < 0 (sdPlane's inside).
float tracePlane(vec3 ro, vec3 rd, vec3 n, float h) {
    float height = dot(ro, n) + h;
    if (height < 0.0) return 0.0;  // the origin is inside: hit at once, as a march would stop
    float rate = dot(rd, n);
    return rate < 0.0 ? height / -rate : -1.0;
}

// The clearance: the signed angle between the ray and the highest point of the plane within
// tmax, seen from ro. Points of the plane at distance s lie asin(height / s) below the
// horizontal, so the highest within reach are at s = tmax; the ray's own elevation above the
// horizontal is asin(ω·n). At tmax = ∞ this is the elevation: a half-space hides the lower half
// of the sky from any point above it. Inside (height < 0) the ray is hidden outright.
float clearancePlane(vec3 ro, vec3 rd, vec3 n, float h, float tmax) {
    float height = dot(ro, n) + h;
    if (height < 0.0) return -3.14159265;
    return asin(clamp(dot(rd, n), -1.0, 1.0)) + asin(min(height / tmax, 1.0));
}

// source: snippets/trace/sphere.glsl:10
// ro is the ray's origin relative to the sphere's centre, rd a unit direction.
//
// The hit. The ray's closest approach to the centre is q = ro − b·rd, b = ro·rd, so the chord's
// half length is √(r² − |q|²): written that way, not as √(b² − c), it keeps its precision when
// the sphere is small and far (b² and c then agree in most of their digits). The near root
// −b − √h is taken as c / (−b + √h), its exact rewrite without the cancellation.
float traceSphere(vec3 ro, vec3 rd, float r) {
    float b = dot(ro, rd);
    vec3 q = ro - b * rd;
    float h = r * r - dot(q, q);
    float c = dot(ro, ro) - r * r;
    if (c < 0.0) return 0.0;  // the origin is inside: hit at once, as a march would stop
    if (h < 0.0 || b > 0.0) return -1.0;  // misses, or the sphere lies behind
    return c / (-b + sqrt(h));
}

// The clearance: the signed angle between the ray and the sphere's outline seen from ro,
// positive when the ray passes outside it. The outline is a circle of angular radius
// asin(r / |ro|) about the direction to the centre, so the clearance is the angle to the centre
// minus that radius: exact, where an SDF march only samples h/t along the ray. The angle to
// the centre is taken as atan(|ω × c|, ω·c), accurate at small angles where acos is not. A
// sphere wholly beyond tmax does not count (π: far clear).
float clearanceSphere(vec3 ro, vec3 rd, float r, float tmax) {
    float dist = max(length(ro), 1e-20);  // at the centre itself the ray is inside
    if (dist - r > tmax) return 3.14159265;
    vec3 toCentre = -ro;
    float centre = atan(length(cross(rd, toCentre)), dot(rd, toCentre));
    return centre - asin(min(r / dist, 1.0));
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

// source: snippets/D/ggx.glsl:14
// Floor of (NoH² (a² − 1) + 1): it is 0 at a = 0, NoH = 1, where D is a Dirac spike (0/0).
#define MIN_GGX_DENOM 1e-15

// D(h) = a² / (π ((n·h)² (a² − 1) + 1)²). Takes a = roughness², never roughness.
// In float32 the denominator loses digits by cancellation next to NoH = 1 at low roughness
// (about 3% at a = 0.002); D.ggx_mediump avoids it.
float distribution(float NoH, float a) {
    float h = clamp(NoH, 0.0, 1.0);
    float a2 = a * a;
    float d = max(h * h * (a2 - 1.0) + 1.0, MIN_GGX_DENOM);
    return a2 / (PI * d * d);
}

// source: snippets/F/schlick.glsl:14
// F = f0 + (1 − f0)(1 − cosθ)⁵ (Schlick 1994), an approximation of the exact dielectric
// Fresnel: within 0.036 of it at f0 = 0.04, 0.10 at f0 = 0.2 (the budget's domain is
// dielectrics, water to diamond; towards f0 = 1 the exact dielectric has a Brewster dip that
// Schlick lacks). cosTheta is V·H for a light, N·V for the environment; never N·L.
// 1 − cosTheta is clamped: pow of a negative base is undefined in GLSL.
vec3 fresnel(vec3 f0, float cosTheta) {
    return f0 + (1.0 - f0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
}

// source: snippets/V/smith_ggx_correlated.glsl:14
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

// source: snippets/diffuse/lambert.glsl:14
vec3 diffuse(Surface s, Dots d) {
    return s.diffuseColor * (d.NoL / PI);
}

// source: snippets/specular/cook_torrance.glsl:16
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

// source: snippets/specocc/power.glsl:14
float specularOcclusion(float NoV, float ao, float a) {
    return clamp(pow(NoV + ao, a) - 1.0 + ao, 0.0, 1.0);
}

// source: snippets/env/gradient.glsl:11
vec3 environment(vec3 dir) {
    return mix(ENV_BOTTOM, ENV_TOP, clamp(dir.y * 0.5 + 0.5, 0.0, 1.0));
}

// source: snippets/ibl/env_brdf_approx.glsl:16
// The split sum (Karis 2013) factors specular environment light into the environment seen
// around the mirror direction times the BRDF's directional albedo, f0·A + B. Here A and B
// come from Karis's analytic fit instead of a lookup table, and the environment is sampled
// once along R without prefiltering (fine for a smooth sky, too sharp for a rough mirror of
// a detailed one).
//
// Error of (A, B) against the float64 split sum with GGX, height-correlated Smith and Schlick
// (compiler/verify/references/environment.dfg_split_sum), roughness and NoV in [0, 1]: see
// tests/verify/test_environment_light.py. The fit was made for a table with a different masking
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
    // Roll (radians): the screen turns counterclockwise under the picture, which turns clockwise.
    float c = cos(CAMERA_ROLL);
    float r = sin(CAMERA_ROLL);
    uv = mat2(c, r, -r, c) * uv;
    float angle = CAMERA_START + iTime * CAMERA_SPEED;
    float height = CAMERA_HEIGHT;
    if (iMouse.x > 0.0 || iMouse.y > 0.0) {
        angle = 6.28318531 * iMouse.x / iResolution.x;
        height = 2.0 * CAMERA_HEIGHT * iMouse.y / iResolution.y;
    }
    ro = CAMERA_TARGET + vec3(CAMERA_RADIUS * cos(angle), height, CAMERA_RADIUS * sin(angle));
    vec3 ww = normalize(CAMERA_TARGET - ro);
    // Looking straight up or down, ww x y vanishes: the screen's x is then the world's, and
    // its up -z looking down (+z looking up), as for a camera tilted from looking along -z.
    vec3 uu = vec3(1.0, 0.0, 0.0);
    if (dot(ww.xz, ww.xz) > 1e-8) uu = normalize(cross(ww, vec3(0.0, 1.0, 0.0)));
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
// How far the march may have stopped from the surface at this pixel's hit
// (marchTolerance): shadow rays start that far out along the normal.
float hitLift = 0.0;

// source: <generated>:1
// The scene's signed distance: the union of its objects.
float map(vec3 p) {
    float d = sdSphere(p, 1.0);
    d = min(d, sdPlane(p, vec3(0.0, 1.0, 0.0), 1.0));
    return d;
}

// source: snippets/ao/sdf5.glsl:16
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
// The material at a hit point.
Surface surfaceAt(vec3 P, vec3 N, vec3 V) {
    int id = materialAt(P);
    if (id == 1) {
        return makeSurface(P, N, V, mix(MAT_GROUND_ALBEDO, vec3(0.6, 0.6, 0.6), checker(P)), MAT_GROUND_ROUGHNESS);
    }
    return makeSurface(P, N, V, MAT_RED_ALBEDO, MAT_RED_ROUGHNESS);
}

// source: <generated>:1
// The nearer of two hits, where -1 is none.
float nearestHit(float t, float hit) {
    return hit >= 0.0 && (t < 0.0 || hit < t) ? hit : t;
}

// The first hit of the ray before tmax among the scene's objects, or -1.
float traceScene(vec3 ro, vec3 rd, float tmax) {
    float t = -1.0;
    t = nearestHit(t, traceSphere(ro, rd, 1.0));
    t = nearestHit(t, tracePlane(ro, rd, vec3(0.0, 1.0, 0.0), 1.0));
    return t <= tmax ? t : -1.0;
}

// The least signed angle between the ray and an object's outline (negative inside);
// angles past reach need not be exact.
float sceneClearance(vec3 ro, vec3 rd, float tmax, float reach) {
    float c = clearanceSphere(ro, rd, 1.0, tmax);
    c = min(c, clearancePlane(ro, rd, vec3(0.0, 1.0, 0.0), 1.0, tmax));
    return c;
}

// The normal of the object whose surface p lies on (the least |distance|).
vec3 sceneNormal(vec3 p) {
    float best = abs(sdSphere(p, 1.0));
    vec3 n = normalize(p);
    float d1 = abs(sdPlane(p, vec3(0.0, 1.0, 0.0), 1.0));
    if (d1 < best) { best = d1; n = vec3(0.0, 1.0, 0.0); }
    return n;
}

// source: snippets/shadow/analytic.glsl:17
// shadow.soft_centered estimates x, the ray's signed angular distance to an occluder's edge in
// units of the light's radius atan(1/k), from samples k·h/t of a march. For a sphere, a box or
// a plane that angle has a closed form (snippets/trace/: the outline of a sphere is a circle, a
// box's is made of its silhouette edges, a half-space's horizon is a great circle), so here it
// is exact and costs one evaluation per object instead of up to SHADOW_STEPS of the scene. The
// disc's visible fraction is then the same cubic fit of a straight edge as soft_centered's.
// The ray starts tmin along rd, as the march does: a point on a surface is then off it on the
// side the light is, and occluded by it only when the light is below its tangent plane.
float shadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float radius = max(atan(1.0 / SHADOW_K), 1e-6);  // the disc light's angular radius
    float x = sceneClearance(ro + rd * tmin, rd, tmax, radius) / radius;
    x = clamp(x, -1.0, 1.0);
    return 0.25 * (1.0 + x) * (1.0 + x) * (2.0 - x);
}

// source: snippets/normal/analytic.glsl:10
// For a scene of analytic primitives the composer writes sceneNormal: it finds the object whose
// surface p lies on (the least |distance|, each object's own, as the material lookup does) and
// returns that object's gradient in closed form: (p − c)/|p − c| for a sphere, the face's axis
// for a box, n for a plane. Exact up to rounding, where differences of map() are off by their
// step (and cost 4 to 6 evaluations of the whole scene), and correct at every pixel, unlike
// derivative normals at silhouettes.
vec3 calcNormal(vec3 p) {
    return sceneNormal(p);
}

// source: snippets/raymarch/analytic.glsl:11
// When every object of the scene is a sphere, an axis-aligned box or a plane, the first hit
// has a closed form per object (snippets/trace/), and the composer writes traceScene as the
// nearest of them. That replaces up to MARCH_STEPS evaluations of map() by one evaluation of
// each object's intersection, lands on the surface to rounding (a march stops within its
// tolerance), and has no step budget to run out of at grazing angles.
float raymarch(vec3 ro, vec3 rd) {
    return traceScene(ro, rd, MARCH_FAR);
}

// A closed-form hit lies on the surface to rounding: nothing to lift.
float marchTolerance(float t) {
    return 0.0;
}

// source: <generated>:1
// Light arriving at the eye from a surface point.
vec3 shade(Surface s) {
    float occlusion = ambientOcclusion(s.P, s.N);
    vec3 color = vec3(0.0);
    color += directionalLight(s, SUN_DIR, SUN_COLOR, vec3(shadow(s.P + s.N * hitLift, SUN_DIR, 0.02, 5.0)));
    color += skyLight(s, SKY_COLOR, occlusion);
    color += backLight(s, BACK_DIR, BACK_COLOR, occlusion);
    color += environmentLight(s, occlusion);
    return color;
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
        hitLift = marchTolerance(t);
        color = shade(surfaceAt(P, calcNormal(P), -rd));
    }
    color = outputTransfer(tonemap(color * EXPOSURE));
    fragColor = vec4(color, 1.0);
}
