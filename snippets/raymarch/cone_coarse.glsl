/* ---
id = "raymarch.cone_coarse"
slot = "raymarch"
summary = "Pixel-cone sphere tracing with a secant hit: a cone twice as wide (0.004), at most 48 steps"
preset_of = "raymarch.cone"
params = { MARCH_STEPS = 48, MARCH_PIXEL = 0.004 }
--- */
