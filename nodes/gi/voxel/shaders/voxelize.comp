#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's voxelization, one invocation per triangle of one draw and slab of voxel layers (z,
// the dispatch's y; slab_layers layers keep the loop under lavapipe's 65,535 iterations an
// invocation, which a large slanted triangle's whole bounding box passed): the triangle, in world
// space, marks every voxel of the slab it overlaps (conservative: touching counts), by the separating-axis test of
// Akenine-Moller (2001) against each voxel of its bounding box: the box's three axes (the loop's
// bounds), the triangle's normal and the nine cross products of its edges with the axes. Each
// marked voxel adds the triangle's diffuse colour (base colour x the mean vertex colour x
// (1 - metalness), as gi.lpv's RSM; textures are not read), its unit face normal and one to its
// integer sums: atomics, so the order of triangles does not matter. A triangle with a non-finite
// corner is skipped; a zero-area one marks the voxels it touches with a zero normal.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/scene/gbuffer/shaders/draw_data.glsl"
#include "nodes/gi/common/shaders/triangle_box.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // triangles x slabs (voxel_kernel.cpp)

layout(std430, binding = 1) readonly buffer Draws { Draw draws[]; };
layout(std430, binding = 2) readonly buffer Vertices { float vertices[]; };  // GpuVertex: 18 floats
layout(std430, binding = 3) readonly buffer Indices { uint indices[]; };
layout(std430, binding = 4) buffer Grid { int grid[]; };
layout(push_constant) uniform Push {
  uint draw_index;
  uint first_triangle;
  uint triangle_count;
  uint slab_layers;
};

const uint kVertexFloats = 18u, kColorOffset = 14u;

vec3 vertex_position(uint v) {
  return vec3(vertices[kVertexFloats * v], vertices[kVertexFloats * v + 1u], vertices[kVertexFloats * v + 2u]);
}

vec3 vertex_color(uint v) {
  uint o = kVertexFloats * v + kColorOffset;
  return vec3(vertices[o], vertices[o + 1u], vertices[o + 2u]);
}

void main() {
  if (gl_GlobalInvocationID.x >= triangle_count) return;
  uint t = first_triangle + gl_GlobalInvocationID.x;
  int first_layer = int(gl_GlobalInvocationID.y * slab_layers);
  Draw d = draws[draw_index];
  uint i0 = indices[3u * t], i1 = indices[3u * t + 1u], i2 = indices[3u * t + 2u];
  vec3 origin = voxel.origin_cell.xyz;
  float cell = voxel.origin_cell.w;
  // Grid units: voxel (i, j, k) spans [i, i + 1] x [j, j + 1] x [k, k + 1].
  vec3 a = ((d.world * vec4(vertex_position(i0), 1.0)).xyz - origin) / cell;
  vec3 b = ((d.world * vec4(vertex_position(i1), 1.0)).xyz - origin) / cell;
  vec3 c = ((d.world * vec4(vertex_position(i2), 1.0)).xyz - origin) / cell;
  if (!all_finite(vec4(a, 0.0)) || !all_finite(vec4(b, 0.0)) || !all_finite(vec4(c, 0.0))) return;

  vec3 mean_color = (vertex_color(i0) + vertex_color(i1) + vertex_color(i2)) / 3.0;
  vec3 albedo = clamp(finite_or_zero(d.base_color.rgb * mean_color * (1.0 - d.material.y)), 0.0, 1.0);
  vec3 n = cross(b - a, c - a);
  float len = length(n);
  vec3 unit_normal = len > 1e-12 && !isinf(len) ? n / len : vec3(0.0);
  ivec3 albedo_fixed = ivec3(round(albedo * kVoxelUnit));
  ivec3 normal_fixed = ivec3(round(unit_normal * kVoxelUnit));

  ivec3 counts = voxel.counts.xyz;
  ivec3 lo = clamp(ivec3(floor(min(a, min(b, c)))), ivec3(0), counts - 1);
  ivec3 hi = clamp(ivec3(floor(max(a, max(b, c)))), ivec3(0), counts - 1);
  if (any(greaterThan(min(a, min(b, c)), vec3(counts))) || any(lessThan(max(a, max(b, c)), vec3(0.0)))) return;
  for (int z = max(lo.z, first_layer); z <= min(hi.z, first_layer + int(slab_layers) - 1); ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        vec3 centre = vec3(x, y, z) + 0.5;
        if (!triangle_overlaps_box(a - centre, b - centre, c - centre, n)) continue;
        uint base = LG_VOXEL_INTS * voxel_index(ivec3(x, y, z));
        atomicAdd(grid[base], albedo_fixed.r);
        atomicAdd(grid[base + 1u], albedo_fixed.g);
        atomicAdd(grid[base + 2u], albedo_fixed.b);
        atomicAdd(grid[base + 3u], normal_fixed.x);
        atomicAdd(grid[base + 4u], normal_fixed.y);
        atomicAdd(grid[base + 5u], normal_fixed.z);
        atomicAdd(grid[base + 6u], 1);
      }
}
