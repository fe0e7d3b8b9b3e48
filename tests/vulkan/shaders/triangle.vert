#version 450
// One triangle from gl_VertexIndex: apex at the top of the image (Vulkan NDC y points down).
const vec2 kPositions[3] = vec2[](vec2(0.0, -0.75), vec2(-0.75, 0.75), vec2(0.75, 0.75));
layout(push_constant) uniform Push { vec4 color; float depth; } push;
void main() { gl_Position = vec4(kPositions[gl_VertexIndex], push.depth, 1.0); }
