GLSLShader Common { #version 450
  vec3 shade(vec3 n) { return n * 0.5 + 0.5; } }
GLSLShader FS { layout(location = 0) out vec4 color; void main() { color = vec4(shade(vec3(1)), 1); } }
technique Glsl { pass { FragmentProgram = { Common, FS }; } }
