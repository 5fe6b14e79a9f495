#version 460
#extension GL_GOOGLE_include_directive : require
// gi.lpv's lookup, one invocation per G-buffer pixel: the summed intensity trilinearly half a
// cell out along the normal (the sampler filters lpv_store.comp's images, edges clamped), as
// radiance over a cell face (intensity / cell^2), read as a lobe (sh_l1_lobe) and convolved with
// the cosine about the normal for the light arriving at it (travelling along -n); plus the sky's
// light (lpv_sky.comp; not read without it, kAddSky) at the same point: the filtered radiance over the
// filtered openness, its L1 convolved with the cosine (linear: an open hemisphere gives pi L).
// rgb: irradiance, W/m^2; a: coverage, 1
// where the surface lies in the grid's box, 0 outside it, on the sky and in a frame with neither
// a directional light nor the sky injected (scales.z). The target is the output itself, or at resolution_scale 1/k below
// 1 a smaller image whose texel i is the G-buffer's texel upsample_source_texel(i, k), which
// gi.irradiance_volume's upsample.comp brings back to full resolution.
#include "nodes/gi/lpv/shaders/lpv_common.glsl"
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 1) uniform CameraBlock { Camera camera; };  // at the G-buffer's size
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 3) uniform sampler2D normal_tex;
layout(binding = 4) uniform sampler3D sum_red;
layout(binding = 5) uniform sampler3D sum_green;
layout(binding = 6) uniform sampler3D sum_blue;
layout(binding = 7, rgba16f) uniform writeonly image2D irradiance;
layout(binding = 8) uniform sampler3D sky_red;
layout(binding = 9) uniform sampler3D sky_green;
layout(binding = 10) uniform sampler3D sky_blue;
layout(binding = 11) uniform sampler3D sky_openness;
// 0 without the sky (no SH linked): its images, bound all the same, are not read (a branch on a
// uniform would fetch them anyway on lavapipe, docs/lavapipe-costs.md rule 1).
layout(constant_id = 0) const int kAddSky = 1;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the target's
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(irradiance)))) return;
  ivec2 source = upsample_source_texel(texel, k, textureSize(depth_tex, 0));
  float depth = texelFetch(depth_tex, source, 0).r;
  float cell = lpv.origin_cell.w;
  vec3 p = depth > 0.0 ? world_position(camera, source, depth) : vec3(0.0);
  vec3 g = (p - lpv.origin_cell.xyz) / cell;
  if (!(depth > 0.0) || !all_finite(vec4(p, 0.0)) || any(lessThan(g, vec3(0.0))) ||
      any(greaterThan(g, vec3(lpv.counts.xyz)))) {
    imageStore(irradiance, texel, vec4(0.0));
    return;
  }
  vec3 n = decode_normal(texelFetch(normal_tex, source, 0).rgb);
  vec3 uvw = (g + 0.5 * n) / vec3(lpv.counts.xyz);  // texel centres at (i + 0.5) / counts, as cell centres
  vec4 sh[3] = vec4[3](textureLod(sum_red, uvw, 0.0), textureLod(sum_green, uvw, 0.0), textureLod(sum_blue, uvw, 0.0));
  // lpv_store.comp stored radiance; the light arriving travels along w with w . n < 0.
  vec3 e = vec3(sh_l1_lobe_convolve(sh_l1_lobe(sh[0]), -n), sh_l1_lobe_convolve(sh_l1_lobe(sh[1]), -n),
                sh_l1_lobe_convolve(sh_l1_lobe(sh[2]), -n));
  if (kAddSky != 0) e += lpv_sky_irradiance(sky_red, sky_green, sky_blue, sky_openness, uvw, n);
  imageStore(irradiance, texel, vec4(clamp(finite_or_zero(max(e, vec3(0.0))), 0.0, 65504.0), lpv.scales.z));
}
