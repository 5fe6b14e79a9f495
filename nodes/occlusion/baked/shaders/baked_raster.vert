#version 460
#extension GL_GOOGLE_include_directive : require
// Transforms one mesh as the G-buffer pass does and passes on its bake: a vertex bake's bent
// normal (turned by the normal matrix) and k_A, or the lightmap UV (texel bakes are drawn from
// the kernel's own vertex buffer, three vertices a triangle, uv = the corner's lightmap UV).
#include "nodes/occlusion/baked/shaders/baked_draw.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec4 vertex_bake;
layout(location = 2) out vec2 lightmap_uv;

void main() {
  Draw d = draws[draw_index];
  BakedDraw b = baked_draws[draw_index];
  world_normal = mat3(d.normal_matrix) * normal;
  vertex_bake = vec4(0.0);
  if (b.kind == kVertexBake) {
    vec4 v = vertex_occlusion[b.vertex_base + uint(gl_VertexIndex)];
    vertex_bake = vec4(mat3(d.normal_matrix) * v.xyz, v.w);
  }
  lightmap_uv = uv;
  gl_Position = camera.view_projection * (d.world * vec4(position, 1.0));
}
