"""P, portability: what GLSL ES 3.00 and ShaderToy reject although desktop drivers or older
ShaderToy accepted it: the mainImage entry point, ES 1.00 names, implicit int-to-float
conversion, non-constant global initialisers, reserved words. One module per rule; shared
helpers in `_common`."""
