#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's geometry volume from the scene's draws, one invocation per triangle of one draw and
// slab of cell layers (as gi.voxel's voxelize.comp: the loop stays under lavapipe's 65,535
// iterations): every cell the triangle overlaps (triangle_box.glsl) gets its blocking potential,
// min(area / cell^2, 1) x the cosine lobe of its normal (Kaplanyan and Dachsbacher), in
// fixed point with integer atomics (order-independent); beside it, for the sky's march
// (lpv_sky.comp), the same weight times the triangle's plane: its normal turned to the side of
// kPlaneSide (so that the two faces of a slab add up, not cancel) and its signed distance from
// the cell's centre along that normal, summed into the cell's mean plane; and its diffuse colour
// (base colour x the mean vertex colour x (1 - metalness), as gi.voxel's), for the sky's light
// the cell's surfaces reflect (lpv_sky_bounce.comp). Every surface blocks, lit or not and seen
// by the camera or not: from the RSM's surfels alone, a wall in shadow did not block, and light
// leaked through it. The normal is the face's, turned to the side the vertex normals face.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/scene/gbuffer/shaders/draw_data.glsl"
#include "nodes/gi/common/shaders/triangle_box.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // triangles x slabs (lpv_kernel.cpp)

layout(std430, binding = 1) readonly buffer Draws { Draw draws[]; };
layout(std430, binding = 2) readonly buffer Vertices { float vertices[]; };  // GpuVertex: 18 floats
layout(std430, binding = 3) readonly buffer Indices { uint indices[]; };
// 12 a cell: the lobe's four coefficients, the planes' weighted normals (x, y, z) and distances,
// the weighted diffuse colour (r, g, b) and one unused.
layout(std430, binding = 4) buffer OcclusionFixed { int occlusion_fixed[]; };
layout(push_constant) uniform Push {
  uint draw_index;
  uint first_triangle;
  uint triangle_count;
  uint slab_layers;
};

// Off every axis and diagonal, so that no wall of a box turns its faces both ways.
const vec3 kPlaneSide = vec3(0.48, 0.57, 0.67);

// GpuVertex's position (floats 0-2), normal (3-5) or colour (14-16).
vec3 vertex_vec3(uint v, uint offset) {
  uint o = 18u * v + offset;
  return vec3(vertices[o], vertices[o + 1u], vertices[o + 2u]);
}

void main() {
  uint t = first_triangle + gl_GlobalInvocationID.x;
  int first_layer = int(gl_GlobalInvocationID.y * slab_layers);
  // The local size's 8 slabs are mostly past the grid (a 16-cell grid is one slab): those
  // invocations leave before reading their triangle, or they would read it 8 times over.
  if (gl_GlobalInvocationID.x >= triangle_count || first_layer >= lpv.counts.z) return;
  Draw d = draws[draw_index];
  uint i0 = indices[3u * t], i1 = indices[3u * t + 1u], i2 = indices[3u * t + 2u];
  vec3 origin = lpv.origin_cell.xyz;
  float cell = lpv.origin_cell.w;
  // Grid units: cell (i, j, k) spans [i, i + 1] x [j, j + 1] x [k, k + 1].
  vec3 a = ((d.world * vec4(vertex_vec3(i0, 0u), 1.0)).xyz - origin) / cell;
  vec3 b = ((d.world * vec4(vertex_vec3(i1, 0u), 1.0)).xyz - origin) / cell;
  vec3 c = ((d.world * vec4(vertex_vec3(i2, 0u), 1.0)).xyz - origin) / cell;
  if (!all_finite(vec4(a, 0.0)) || !all_finite(vec4(b, 0.0)) || !all_finite(vec4(c, 0.0))) return;
  vec3 n = cross(b - a, c - a);
  float len = length(n);  // twice the area, in cells^2
  if (!(len > 1e-12) || isinf(len)) return;
  vec3 unit_normal = n / len;
  vec3 vertex_normals = mat3(d.normal_matrix) * (vertex_vec3(i0, 3u) + vertex_vec3(i1, 3u) + vertex_vec3(i2, 3u));
  if (dot(vertex_normals, unit_normal) < 0.0) unit_normal = -unit_normal;
  float weight = min(0.5 * len, 1.0) * lpv.scales.y;
  ivec4 v = ivec4(round(weight * sh_l1_cosine_lobe(unit_normal)));
  vec3 color = (vertex_vec3(i0, 14u) + vertex_vec3(i1, 14u) + vertex_vec3(i2, 14u)) / 3.0;
  ivec3 albedo = ivec3(round(weight * clamp(finite_or_zero(d.base_color.rgb * color * (1.0 - d.material.y)), 0.0, 1.0)));
  vec3 side_normal = dot(unit_normal, kPlaneSide) < 0.0 ? -unit_normal : unit_normal;

  ivec3 counts = lpv.counts.xyz;
  if (any(greaterThan(min(a, min(b, c)), vec3(counts))) || any(lessThan(max(a, max(b, c)), vec3(0.0)))) return;
  ivec3 lo = clamp(ivec3(floor(min(a, min(b, c)))), ivec3(0), counts - 1);
  ivec3 hi = clamp(ivec3(floor(max(a, max(b, c)))), ivec3(0), counts - 1);
  for (int z = max(lo.z, first_layer); z <= min(hi.z, first_layer + int(slab_layers) - 1); ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        if (!triangle_overlaps_box(a - (vec3(x, y, z) + 0.5), b - (vec3(x, y, z) + 0.5), c - (vec3(x, y, z) + 0.5), n))
          continue;
        uint base = 12u * lpv_cell_index(ivec3(x, y, z));
        for (int k = 0; k < 4; ++k)
          if (v[k] != 0) atomicAdd(occlusion_fixed[base + uint(k)], v[k]);
        // The distance is within sqrt(3) / 2 cells: the plane crosses the cell.
        ivec4 plane = ivec4(round(weight * vec4(side_normal, dot(a - (vec3(x, y, z) + 0.5), side_normal))));
        for (int k = 0; k < 4; ++k)
          if (plane[k] != 0) atomicAdd(occlusion_fixed[base + 4u + uint(k)], plane[k]);
        for (int k = 0; k < 3; ++k)
          if (albedo[k] != 0) atomicAdd(occlusion_fixed[base + 8u + uint(k)], albedo[k]);
      }
}
