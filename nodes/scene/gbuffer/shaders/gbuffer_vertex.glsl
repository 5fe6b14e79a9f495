// The G-buffer's vertex stage: one mesh into clip space, passing on what the fragment stage
// (gbuffer_surface.glsl) stores; with LG_MATERIAL_MAPS also both uv sets, the tangent frame,
// the vertex colour and the world position its material needs. With LG_DRAW_BLOCK (the
// G-buffer's own variants, gbuffer_plain.vert and gbuffer_maps.vert) the draw comes from
// draw.glsl's uniform block.
#include "nodes/scene/gbuffer/shaders/draw.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;  // in every variant: GpuVertex's basic attributes (use_gpu_vertices)
layout(location = 0) out vec3 world_normal;
layout(location = 2) out vec4 clip_now;
layout(location = 3) out vec4 clip_before;
#ifdef LG_MATERIAL_MAPS
layout(location = 3) in vec2 uv1;
layout(location = 4) in vec4 tangent;  // 0 where the mesh has none
layout(location = 5) in vec4 color;
layout(location = 1) out vec4 texcoords;  // set 0 in xy, set 1 in zw
layout(location = 4) out vec3 surface_position;
layout(location = 5) out vec4 world_tangent;  // w: the bitangent's sign
layout(location = 6) out vec4 vertex_color;
#endif

void main() {
#ifdef LG_DRAW_BLOCK
  Draw d = this_draw;
#else
  Draw d = draws[draw_index];
#endif
  vec4 world = d.world * vec4(position, 1.0);
  world_normal = mat3(d.normal_matrix) * normal;
#ifdef LG_MATERIAL_MAPS
  // Tangents follow the surface (the world matrix, not the normal matrix); a mirroring matrix
  // flips cross(n, t), which the sign makes up for.
  world_tangent = vec4(mat3(d.world) * tangent.xyz, determinant(mat3(d.world)) < 0.0 ? -tangent.w : tangent.w);
  texcoords = vec4(uv, uv1);
  vertex_color = color;
  surface_position = world.xyz;
#endif
  clip_now = camera.view_projection * world;
  clip_before = camera.previous_view_projection * (d.previous_world * vec4(position, 1.0));
  gl_Position = clip_now;
}
