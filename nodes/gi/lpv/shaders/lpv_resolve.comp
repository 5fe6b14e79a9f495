#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv: the injected fixed-point sums to floats, one invocation per cell: the light that
// propagation starts from (its lobe part scaled to keep its power in the first step,
// lpv_outflow), the first term of the sum the lookup reads, and the occlusion.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer LightFixed { ivec4 light_fixed[]; };          // 3 a cell
layout(std430, binding = 2) readonly buffer OcclusionFixed { ivec4 occlusion_fixed[]; };  // 1 a cell
layout(std430, binding = 3) writeonly buffer Light { vec4 light[]; };                     // 3 a cell
layout(std430, binding = 4) writeonly buffer Sum { vec4 sum[]; };                         // 3 a cell
layout(std430, binding = 5) writeonly buffer Occlusion { vec4 occlusion[]; };             // 1 a cell

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  uint i = lpv_cell_index(c);
  for (uint ch = 0u; ch < 3u; ++ch) {
    vec4 v = vec4(light_fixed[3u * i + ch]) / lpv.scales.x;
    light[3u * i + ch] = lpv_outflow(v);
    sum[3u * i + ch] = v;
  }
  occlusion[i] = vec4(occlusion_fixed[i]) / lpv.scales.y;
}
