#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv: the sky's light the surfaces reflect, one invocation per cell, after the sky's march
// (lpv_sky.comp) and before the propagation. A cell gathers from its six face neighbours what
// their surfaces facing it reflect of the sky: the neighbour's mean plane (lpv_resolve.comp) and
// lobe give the side its surfaces face (the lobe's direction where they face one way, else the
// plane's normal turned towards this cell: both faces of a slab reflect, each to its own side),
// the sky's irradiance on that side is read as the lookup reads it (lpv_lookup.comp), a cell
// further out along the normal, and the reflected flux, mean diffuse colour x E x the surfaces'
// coverage of the cell's face, is a virtual point light in this cell, as the sun's are half a cell
// out from their surface (lpv_inject.comp): a Lambertian emitter about the side's normal, split
// among the neighbours the side faces by the squared cosines. Added to the injected light, so the
// propagation carries it, and to the sum.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// lpv_voxelize.comp's sums, 3 a cell: the lobe, the planes, the diffuse colour (fixed point).
layout(std430, binding = 1) readonly buffer OcclusionFixed { ivec4 occlusion_fixed[]; };
layout(binding = 2) uniform sampler3D sky_red;
layout(binding = 3) uniform sampler3D sky_green;
layout(binding = 4) uniform sampler3D sky_blue;
layout(binding = 5) uniform sampler3D sky_openness;
layout(std430, binding = 6) buffer Sum { vec4 sum[]; };  // 3 a cell; holds the injected light
layout(binding = 7, rgba32f) uniform writeonly image3D light_red;  // the propagation's start
layout(binding = 8, rgba32f) uniform writeonly image3D light_green;
layout(binding = 9, rgba32f) uniform writeonly image3D light_blue;

// The sky's irradiance on a surface facing m at grid point g (in cells), as the lookup reads it.
vec3 sky_irradiance_at(vec3 g, vec3 m) {
  return lpv_sky_irradiance(sky_red, sky_green, sky_blue, sky_openness, g / vec3(lpv.counts.xyz), m);
}

void main() {
  ivec3 c = lpv_invocation_cell();
  if (!lpv_inside(c)) return;
  float cell = lpv.origin_cell.w;
  vec4 red = vec4(0.0), green = vec4(0.0), blue = vec4(0.0);
  int k = 0;
  do {
    ivec3 e = ivec3(0);
    e[k / 2] = k % 2 == 0 ? 1 : -1;  // from the neighbour towards this cell
    ivec3 x = c - e;
    if (lpv_inside(x)) {
      uint i = 3u * lpv_cell_index(x);
      vec4 lobe_sums = vec4(occlusion_fixed[i]) / lpv.scales.y;
      vec3 normals = vec3(occlusion_fixed[i + 1u].xyz) / lpv.scales.y;
      float weights = lobe_sums.x / kCosineY00;
      ShLobe lobe = sh_l1_lobe(lobe_sums);
      float len = length(normals);
      // One way where the lobe is mostly direction (a single face), else the plane's two sides.
      vec3 m = lobe.b > 4.0 * lobe.a ? lobe.d : (len > 0.0 ? normals / len : vec3(0.0));
      if (dot(m, vec3(e)) < 0.0 && !(lobe.b > 4.0 * lobe.a)) m = -m;
      float towards = max(dot(m, vec3(e)), 0.0);
      if (weights > 1e-4 && towards > 0.0) {
        vec3 albedo = clamp(vec3(occlusion_fixed[i + 2u].xyz) / (lpv.scales.y * weights), 0.0, 1.0);
        vec3 e_sky = sky_irradiance_at(vec3(x) + 0.5 + 1.0 * m, m);
        // W: colour x W/m^2 x the covered cell face (m^2), this cell's share of it.
        vec3 flux = albedo * e_sky * (min(len, 1.0) * cell * cell * towards * towards);
        vec4 emitter = sh_l1_cosine_lobe(m) / LG_PI;  // intensity per W of a Lambertian emitter
        red += flux.r * emitter, green += flux.g * emitter, blue += flux.b * emitter;
      }
    }
  } while (++k < 6);
  uint i = 3u * lpv_cell_index(c);
  red = sum[i] + finite_or_zero(red), green = sum[i + 1u] + finite_or_zero(green), blue = sum[i + 2u] + finite_or_zero(blue);
  sum[i] = red, sum[i + 1u] = green, sum[i + 2u] = blue;
  imageStore(light_red, c, lpv_outflow(red));
  imageStore(light_green, c, lpv_outflow(green));
  imageStore(light_blue, c, lpv_outflow(blue));
}
