// A triangle that covers the viewport, at a depth given by a push constant.
#version 460
layout(push_constant) uniform Constants { vec2 size; float depth; };

void main() {
  vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(uv * 2 - 1, depth, 1);
}
