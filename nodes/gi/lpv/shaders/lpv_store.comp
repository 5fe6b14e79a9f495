#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv: the summed light into three 3D images (one per colour channel, SH L1 in rgba), one
// invocation per cell, so that the lookup filters it trilinearly in the sampler (one fetch a
// channel instead of eight). Stored as radiance, intensity over a cell face (intensity / cell^2):
// a small cell's intensities fall below the half floats' normal range (6e-5), radiance is of the
// order of the irradiance it gives. Kept finite and within the half floats' range.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer Sum { vec4 sum[]; };  // 3 a cell
layout(binding = 2, rgba16f) uniform writeonly image3D red;
layout(binding = 3, rgba16f) uniform writeonly image3D green;
layout(binding = 4, rgba16f) uniform writeonly image3D blue;

vec4 storable(vec4 v) {
  return clamp(finite_or_zero(v), vec4(-65504.0), vec4(65504.0));
}

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  uint i = lpv_cell_index(c);
  float to_radiance = 1.0 / (lpv.origin_cell.w * lpv.origin_cell.w);
  imageStore(red, c, storable(sum[3u * i] * to_radiance));
  imageStore(green, c, storable(sum[3u * i + 1u] * to_radiance));
  imageStore(blue, c, storable(sum[3u * i + 2u] * to_radiance));
}
