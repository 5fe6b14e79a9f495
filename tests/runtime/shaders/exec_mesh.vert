// Executor tests: draws a GpuScene mesh whose positions are already in clip space, passing its
// normal and uv on unchanged (flat: no interpolation error).
#version 460
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) flat out vec3 out_normal;
layout(location = 1) flat out vec2 out_uv;

void main() {
  out_normal = normal;
  out_uv = uv;
  gl_Position = vec4(position, 1);
}
