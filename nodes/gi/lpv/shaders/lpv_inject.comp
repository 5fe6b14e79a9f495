#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's injection, one invocation per RSM texel. Its virtual point light (flux = the texel's
// reflected flux per m^2 of beam x the texel's beam area, a Lambertian emitter of intensity
// flux / pi x max(0, n . w)) goes to the cell half a cell out along its normal, so a surface does
// not light itself. (The geometry volume comes from the draws, lpv_voxelize.comp.)
// Sums are fixed-point integers (scales from lpv_kernel.cpp keep the whole map's total in range),
// so the result does not depend on the order the atomics land in.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D rsm_position;
layout(binding = 2) uniform sampler2D rsm_normal;
layout(binding = 3) uniform sampler2D rsm_flux;
layout(std430, binding = 4) buffer LightFixed { int light_fixed[]; };  // 12 a cell: channel-major

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ivec2(lpv.counts.w)))) return;
  vec4 p = texelFetch(rsm_position, texel, 0);
  vec3 n = texelFetch(rsm_normal, texel, 0).xyz;
  vec3 flux = texelFetch(rsm_flux, texel, 0).rgb * lpv.light.w;
  if (p.a < 0.5 || !all_finite(vec4(p.xyz, 0.0)) || !all_finite(vec4(n, 0.0)) || !all_finite(vec4(flux, 0.0))) return;
  float len = length(n);
  if (!(len > 1e-3)) return;
  n /= len;
  float cell = lpv.origin_cell.w;
  vec4 lobe = sh_l1_cosine_lobe(n);

  ivec3 c = ivec3(floor((p.xyz + 0.5 * cell * n - lpv.origin_cell.xyz) / cell));
  if (!lpv_inside(c)) return;
  uint base = 12u * lpv_cell_index(c);
  for (int ch = 0; ch < 3; ++ch) {
    ivec4 v = ivec4(round(clamp(max(flux[ch], 0.0) / LG_PI * lobe * lpv.scales.x, -1e9, 1e9)));
    for (int k = 0; k < 4; ++k)
      if (v[k] != 0) atomicAdd(light_fixed[base + 4u * uint(ch) + uint(k)], v[k]);
  }
}
