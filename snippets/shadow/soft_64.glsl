/* ---
id = "shadow.soft_64"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 64 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 64 }
--- */
