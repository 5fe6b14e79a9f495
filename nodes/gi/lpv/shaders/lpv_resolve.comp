#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv: the injected fixed-point sums to floats, one invocation per cell: the light that
// propagation starts from (in lpv_outflow's form, its lobe part scaled to keep its power in the
// first step), the first term of the sum the lookup reads, and the occlusion (read as a lobe
// too, sh_l1_lobe: a surface blocks the light that travels into it, not the light that runs
// along it). The light and the occlusion go to 3D images, which lpv_propagate.comp reads with
// texelFetch (lavapipe gathers those; a storage buffer's vec4 it reads lane by lane).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer LightFixed { ivec4 light_fixed[]; };          // 3 a cell
layout(std430, binding = 2) readonly buffer OcclusionFixed { ivec4 occlusion_fixed[]; };  // 1 a cell
layout(binding = 3, rgba32f) uniform writeonly image3D light_red;
layout(binding = 4, rgba32f) uniform writeonly image3D light_green;
layout(binding = 5, rgba32f) uniform writeonly image3D light_blue;
layout(std430, binding = 6) writeonly buffer Sum { vec4 sum[]; };  // 3 a cell
layout(binding = 7, rgba32f) uniform writeonly image3D occlusion;

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  uint i = lpv_cell_index(c);
  vec4 red = vec4(light_fixed[3u * i]) / lpv.scales.x, green = vec4(light_fixed[3u * i + 1u]) / lpv.scales.x,
       blue = vec4(light_fixed[3u * i + 2u]) / lpv.scales.x;
  imageStore(light_red, c, lpv_outflow(red));
  imageStore(light_green, c, lpv_outflow(green));
  imageStore(light_blue, c, lpv_outflow(blue));
  sum[3u * i] = red;
  sum[3u * i + 1u] = green;
  sum[3u * i + 2u] = blue;
  imageStore(occlusion, c, sh_l1_lobe_packed(sh_l1_lobe(vec4(occlusion_fixed[i]) / lpv.scales.y)));
}
