/* ---
id = "shadow.soft_12"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 12 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 12 }
error_budget = { max_abs = 1.0, mean_abs = 0.065 }
budget_why = "12 steps reach only t ≤ 2.4 and miss the far occluders of low suns: against a disc light, mean 0.053 over 10460 points and max 1.0 (a whole shadow missed); the budget is about 1.2x the mean, max 1."
--- */
