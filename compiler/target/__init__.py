"""What a shader runs in: the ShaderToy prelude and its uniforms, glslangValidator, and the
source markers that map the emitted lines back to snippet files."""
