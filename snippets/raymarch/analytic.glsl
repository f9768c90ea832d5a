/* ---
id = "raymarch.analytic"
slot = "raymarch"
summary = "No march: the nearest of the scene's closed-form ray hits (every object an analytic primitive)"
provides = ["raymarch", "marchTolerance"]
requires = ["traceScene"]
params = { MARCH_FAR = { type = "float", default = 50.0, range = [1.0, 10000.0] } }
sources = ["Kay and Kajiya 1986, ray tracing complex scenes", "Haines et al. 2019, Precision Improvements for Ray/Sphere Intersection"]
formula = 't_{\text{hit}} = \min_k t_k(\mathbf{o}, \boldsymbol{\omega}) \text{ over the objects } k \text{ the ray meets before } t_{\text{far}}'
--- */
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
