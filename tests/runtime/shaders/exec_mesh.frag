// Executor tests: (normal, uv.x + 1) for every covered pixel.
#version 460
layout(location = 0) flat in vec3 normal;
layout(location = 1) flat in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
  color = vec4(normal, uv.x + 1);
}
