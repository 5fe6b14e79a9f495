#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's reflective shadow map: each draw from the light, through lighting.deferred's
// directional shadow projection (its shadow_draw.glsl bindings: the draw's block at 0), with what
// the fragment needs.
#include "nodes/lighting/deferred/shaders/shadow_draw.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 5) in vec4 color;
layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec3 vertex_color;

void main() {
  Draw d = this_draw;
  vec4 p = d.world * vec4(position, 1.0);
  world_position = p.xyz;
  world_normal = mat3(d.normal_matrix) * normal;
  vertex_color = color.rgb;
  gl_Position = shadow_from_world * p;
}
