/* ---
id = "shadow.soft_64"
slot = "shadow"
summary = "Soft shadow k·h/t, the classic march at 64 steps"
preset_of = "shadow.soft"
params = { SHADOW_STEPS = 64 }
error_budget = { max_abs = 0.75, mean_abs = 0.026 }
budget_why = "The k·h/t estimate at 64 steps against a disc light: mean 0.021 and max 0.68 over 10460 points on llvmpipe; the budget is about 1.25x the mean and 1.1x the max."
--- */
