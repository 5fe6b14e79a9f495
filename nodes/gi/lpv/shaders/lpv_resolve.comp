#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv: the injected fixed-point sums to floats, one invocation per cell: the light that
// propagation starts from (in lpv_outflow's form, its lobe part scaled to keep its power in the
// first step), the first term of the sum the lookup reads, and the occlusion (read as a lobe
// too, sh_l1_lobe: a surface blocks the light that travels into it, not the light that runs
// along it). The light and the occlusion go to 3D images, which lpv_propagate.comp reads with
// texelFetch (lavapipe gathers those; a storage buffer's vec4 it reads lane by lane). Also each
// cell's surfaces as one plane for the sky's march (lpv_sky.comp): its unit normal times how much
// of the cell it covers (the length of the triangles' weighted normals summed, at most 1: a wall
// crossing the cell covers it), and its distance from the cell's centre along that normal, in
// cells (the weighted mean); 0 in an empty cell. Where the surfaces are not one plane (their
// weighted normals, turned to one side, add up to less than 0.9 of their weights: the edge where a
// wall meets a floor), the normal's length is 1 + the coverage instead, and the march blocks every
// ray that passes through the cell (one mean plane there let rays slip past the edges of a closed
// room).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer LightFixed { ivec4 light_fixed[]; };          // 3 a cell
layout(std430, binding = 2) readonly buffer OcclusionFixed { ivec4 occlusion_fixed[]; };  // 3 a cell, the lobe first
layout(binding = 3, rgba32f) uniform writeonly image3D light_red;
layout(binding = 4, rgba32f) uniform writeonly image3D light_green;
layout(binding = 5, rgba32f) uniform writeonly image3D light_blue;
layout(std430, binding = 6) writeonly buffer Sum { vec4 sum[]; };  // 3 a cell
layout(binding = 7, rgba32f) uniform writeonly image3D occlusion;
layout(binding = 8, rgba32f) uniform writeonly image3D sky_planes;

vec4 sky_plane(ivec4 planes, vec4 blocking) {
  vec3 normals = vec3(planes.xyz) / lpv.scales.y;
  float len = length(normals);
  if (!(len > 1e-4)) return vec4(0.0);
  float weights = blocking.x / kCosineY00;  // a cosine lobe's Y00 coefficient
  float coverage = min(len, 1.0) + (len < 0.9 * weights ? 1.0 : 0.0);
  return vec4(normals / len * coverage, float(planes.w) / (lpv.scales.y * len));
}

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
  vec4 blocking = vec4(occlusion_fixed[3u * i]) / lpv.scales.y;
  imageStore(occlusion, c, sh_l1_lobe_packed(sh_l1_lobe(blocking)));
  imageStore(sky_planes, c, sky_plane(occlusion_fixed[3u * i + 1u], blocking));
}
