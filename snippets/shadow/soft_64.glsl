/* ---
id = "shadow.soft_64"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 64 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 64 }
error_budget = { max_abs = 0.75, mean_abs = 0.026 }
--- */
