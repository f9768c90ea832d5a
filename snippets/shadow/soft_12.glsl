/* ---
id = "shadow.soft_12"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 12 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 12 }
error_budget = { max_abs = 1.0, mean_abs = 0.065 }
--- */
