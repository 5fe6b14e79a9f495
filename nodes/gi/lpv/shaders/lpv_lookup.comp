#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's lookup, one invocation per G-buffer pixel: the summed intensity trilinearly half a
// cell out along the normal (the cell centres around that point, clamped to the grid), as
// radiance over a cell face (intensity / cell^2), convolved with the cosine about the normal
// for the light arriving at it (travelling along -n). rgb: irradiance, W/m^2; a: coverage, 1
// where the surface lies in the grid's box, 0 outside it, on the sky and in a frame without a
// directional light (scales.z).
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 1) uniform CameraBlock { Camera camera; };  // at the G-buffer's size
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 3) uniform sampler2D normal_tex;
layout(std430, binding = 4) readonly buffer Sum { vec4 sum[]; };  // 3 a cell
layout(binding = 5, rgba16f) uniform writeonly image2D irradiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(irradiance)))) return;
  float depth = texelFetch(depth_tex, texel, 0).r;
  float cell = lpv.origin_cell.w;
  vec3 p = depth > 0.0 ? world_position(camera, texel, depth) : vec3(0.0);
  vec3 g = (p - lpv.origin_cell.xyz) / cell;
  if (!(depth > 0.0) || !all_finite(vec4(p, 0.0)) || any(lessThan(g, vec3(0.0))) ||
      any(greaterThan(g, vec3(lpv.counts.xyz)))) {
    imageStore(irradiance, texel, vec4(0.0));
    return;
  }
  vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
  vec3 at = g + 0.5 * n - 0.5;  // in cell-centre coordinates
  ivec3 base = ivec3(floor(at));
  vec3 f = at - vec3(base);
  vec4 sh[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    uint i = lpv_cell_index(clamp(base + o, ivec3(0), lpv.counts.xyz - 1));
    float w = w3.x * w3.y * w3.z;
    for (uint ch = 0u; ch < 3u; ++ch) sh[ch] += w * sum[3u * i + ch];
  }
  vec4 lobe = sh_l1_cosine_lobe(-n) / (cell * cell);
  vec3 e = vec3(dot(sh[0], lobe), dot(sh[1], lobe), dot(sh[2], lobe));
  imageStore(irradiance, texel, vec4(clamp(finite_or_zero(max(e, vec3(0.0))), 0.0, 65504.0), lpv.scales.z));
}
