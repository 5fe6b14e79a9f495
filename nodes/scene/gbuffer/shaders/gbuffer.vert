#version 460
#extension GL_GOOGLE_include_directive : require
// Transforms one mesh into clip space, passing on what the fragment stage stores.
#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec2 texcoord;
layout(location = 2) out vec4 clip_now;
layout(location = 3) out vec4 clip_before;

void main() {
  Draw d = draws[draw_index];
  vec4 world = d.world * vec4(position, 1.0);
  world_normal = mat3(d.normal_matrix) * normal;
  texcoord = uv;
  clip_now = camera.view_projection * world;
  clip_before = camera.previous_view_projection * (d.previous_world * vec4(position, 1.0));
  gl_Position = clip_now;
}
