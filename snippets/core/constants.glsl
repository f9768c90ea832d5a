/* ---
id = "core.constants"
slot = "core"
summary = "Mathematical constants shared by every snippet"
provides = ["PI"]
requires = []
sources = ["lighting-model skill, complete code template"]
formula = '\pi = 3.14159265359'
--- */
#define PI 3.14159265359
