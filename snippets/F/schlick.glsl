/* ---
id = "F.schlick"
slot = "F"
summary = "Schlick's Fresnel approximation with pow"
provides = ["fresnel"]
requires = []
domain = { cosTheta = [0, 1] }
sources = ["lighting-model skill, step 4", "Schlick 1994"]
--- */
// cosTheta is V·H for a light, N·V for the environment; never N·L.
vec3 fresnel(vec3 f0, float cosTheta) {
    return f0 + (1.0 - f0) * pow(1.0 - cosTheta, 5.0);
}
