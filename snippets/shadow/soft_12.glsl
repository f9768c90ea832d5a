/* ---
id = "shadow.soft_12"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 12 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 12 }
--- */
