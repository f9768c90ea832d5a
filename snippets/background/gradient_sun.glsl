/* ---
id = "background.gradient_sun"
slot = "background"
summary = "The environment gradient plus a glow and a disc around the sun"
provides = ["background"]
requires = ["env", "SUN_DIR", "SUN_COLOR"]
sources = ["lighting-model skill, complete code template (background)"]
--- */
vec3 background(vec3 rd) {
    float sun = clamp(dot(rd, SUN_DIR), 0.0, 1.0);
    vec3 col = environment(rd);
    col += SUN_COLOR * 0.3 * pow(sun, 8.0);
    col += SUN_COLOR * pow(sun, 256.0);
    return col;
}
