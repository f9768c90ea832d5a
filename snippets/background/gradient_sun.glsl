/* ---
id = "background.gradient_sun"
slot = "background"
summary = "The environment gradient plus a glow and a disc around the sun"
provides = ["background"]
requires = ["env", "SUN_DIR", "SUN_COLOR"]
sources = ["lighting-model skill, complete code template (background)"]
formula = 'L_{\text{bg}}(\boldsymbol{\omega}) = L_{\text{env}}(\boldsymbol{\omega}) + C_{\text{sun}} \left( 0.3\, s^{8} + s^{256} \right), \quad s = \operatorname{clamp}(\boldsymbol{\omega} \cdot \mathbf{l}_{\text{sun}}, 0, 1)'
--- */
vec3 background(vec3 rd) {
    float sun = clamp(dot(rd, SUN_DIR), 0.0, 1.0);
    vec3 col = environment(rd);
    col += SUN_COLOR * 0.3 * pow(sun, 8.0);
    col += SUN_COLOR * pow(sun, 256.0);
    return col;
}
