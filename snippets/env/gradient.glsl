/* ---
id = "env.gradient"
slot = "env"
summary = "Environment as a vertical gradient from ENV_BOTTOM (down) to ENV_TOP (up)"
provides = ["environment"]
requires = []
params = { ENV_TOP = { type = "vec3", default = [0.5, 0.7, 1.0] }, ENV_BOTTOM = { type = "vec3", default = [0.8, 0.85, 0.9] } }
sources = ["lighting-model skill, complete code template (background, simplified IBL)"]
formula = 'L_{\text{env}}(\boldsymbol{\omega}) = C_{\text{bottom}} + (C_{\text{top}} - C_{\text{bottom}}) \operatorname{clamp}\left( \frac{1 + \omega_y}{2}, 0, 1 \right)'
--- */
vec3 environment(vec3 dir) {
    return mix(ENV_BOTTOM, ENV_TOP, clamp(dir.y * 0.5 + 0.5, 0.0, 1.0));
}
