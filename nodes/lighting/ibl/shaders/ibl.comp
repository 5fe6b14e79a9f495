#version 460
#extension GL_GOOGLE_include_directive : require
// lighting.ibl: image-based light of every G-buffer pixel, added to the direct light. Diffuse:
// the albedo's diffuse part / pi times irradiance, from SH irradiance coefficients
// (env.sh_project with convolve_cosine) or from an irradiance map holding E / pi
// (env.irradiance). Occlusion (ibl_occlusion.glsl, docs/env-conventions.md): with bent normals
// and SH, the SH radiance integrated over the visibility cone with the cosine about the normal,
// per unit visibility (directional occlusion); with bent normals and the map, the map along the
// bent normal; with AO alone, the irradiance at the normal. Either is scaled by the visibility:
// the AO input where linked, else the cone's own, through Jimenez et al.'s multi-bounce fit
// with the diffuse albedo when asked. Specular: the prefiltered map at mip roughness (mips - 1)
// along the reflection, through the split sum (ibl_environment.glsl), occluded when asked by the
// cone-cone intersection with bent normals, else by Lagarde's form from AO. The material's own
// occlusion (its glTF occlusion texture, in the G-buffer albedo's alpha) multiplies the
// diffuse visibility and, through Lagarde's form, the specular: image-based light only, never
// direct light. With a probe volume linked (gi.irradiance_volume), the diffuse irradiance is the
// environment's (times intensity) mixed toward the volume's by its coverage, before occlusion.
// With reflection probes linked (gi.reflection_capture: rgb reflected radiance before the BRDF, a
// coverage), the reflected radiance is the prefiltered map's (times intensity) mixed toward
// theirs by the coverage; with screen-space reflections linked (lighting.ssr: the same, a
// confidence), that is mixed toward theirs by the confidence (SSR wins where it is sure), before
// the split sum and specular occlusion.
// Pixels with no surface (depth 0) show the prefiltered mip 0 along the view ray.

// The features a plan uses and the SH coefficient count are specialization constants
// (record_ibl): lavapipe runs both sides of a branch on a uniform value, masked, so every unused
// input's fetch and filter cost time until the compiler could drop them, and a constant count
// unrolls the SH sums into registers and sizes the SH's uniform block (ibl_environment.glsl;
// nodes/lighting/ibl/README.md has the times).
// Flags: 1 diffuse from SH (else the map), 2 direct, 4 ao, 8 bent normals, 16 specular
// occlusion, 32 multi-bounce occlusion, 64 irradiance volume, 128 screen-space reflections, 256
// reflection probes.
layout(constant_id = 0) const uint flags = 0u;
layout(constant_id = 1) const int sh_count = 9;  // coefficients in `sh`, 1 to LG_SH_MAX_COUNT
#define LG_IBL_SH_UNIFORM_COUNT sh_count

#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/env/common/shaders/sh_basis.glsl"
#include "nodes/lighting/ibl/shaders/ibl_environment.glsl"
#include "nodes/lighting/ibl/shaders/ibl_occlusion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D albedo_tex;    // sRGB: the sampler decodes it; a: material occlusion
layout(binding = 4) uniform sampler2D material_tex;  // r: perceptual roughness, g: metalness
layout(binding = 5) uniform sampler2D direct_tex;
layout(binding = 10) uniform sampler2D ao_tex;
layout(binding = 11) uniform sampler2D bent_normal_tex;
layout(binding = 12, rgba16f) uniform writeonly image2D color;
layout(binding = 13) uniform sampler2D volume_tex;  // rgb irradiance (W/m^2), a coverage
layout(binding = 14) uniform sampler2D ssr_tex;     // rgb reflected radiance, a confidence
layout(binding = 15) uniform sampler2D probes_tex;  // rgb reflected radiance, a coverage
layout(push_constant) uniform Push { float intensity; };

// Irradiance through the visibility cone about `bent` per unit visibility (ibl_occlusion.glsl):
// bands 0 to 2 by the cone's moments, band 4 by its zonal factor about the bent normal.
vec3 sh_cone_irradiance(vec3 n, vec3 bent, float cone_cos) {
  float w[9];
  cone_lobe_weights(n, bent, cone_cos, w);
  vec3 e = vec3(0.0);
  for (int k = 0; k < min(sh_count, 9); ++k) e += sh[k].rgb * w[k];
  if (sh_count > 16) {
    float y[LG_SH_MAX_COUNT];
    sh_evaluate(bent, y);
    float band4 = cone_band4_ratio(cone_cos);
    for (int k = 16; k < sh_count; ++k) e += band4 * sh[k].rgb * y[k];
  }
  return max(e, vec3(0.0));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(color)))) return;
  vec3 direct = (flags & 2u) != 0u ? texelFetch(direct_tex, texel, 0).rgb : vec3(0.0);
  float depth = texelFetch(depth_tex, texel, 0).r;
  vec3 eye = camera.position.xyz;
  // A sky pixel (no surface) looks up the prefiltered map along the view ray in the same fetch a
  // surface's reflection uses: lavapipe runs both sides of the branch, so two lookups cost two.
  bool sky = depth <= 0.0;
  vec3 p = world_position(camera, texel, sky ? 1.0 : depth);
  vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
  vec3 v = normalize(eye - p);
  vec4 albedo_occlusion = texelFetch(albedo_tex, texel, 0);
  vec3 albedo = albedo_occlusion.rgb;
  float material_occlusion = albedo_occlusion.a;
  vec2 material = texelFetch(material_tex, texel, 0).rg;
  float roughness = material.r, metalness = material.g;
  vec3 diffuse_color = albedo * (1.0 - metalness);
  vec3 f0 = mix(vec3(0.04), albedo, metalness);
  float n_dot_v = clamp(dot(n, v), 1e-4, 1.0);

  // The visibility cone: axis and half-angle cosine (none written: the open hemisphere).
  bool cones = (flags & 8u) != 0u;
  vec3 bent = n;
  float cone_cos = 0.0;
  if (cones) {
    vec4 texel_cone = texelFetch(bent_normal_tex, texel, 0);
    if (dot(texel_cone.xyz, texel_cone.xyz) > 1e-6) {
      bent = normalize(texel_cone.xyz);
      cone_cos = clamp(texel_cone.w, 0.0, 1.0);
    }
  }
  // How much of the hemisphere's cosine weight is visible: the AO input, else the cone's own.
  float visibility = (flags & 4u) != 0u ? texelFetch(ao_tex, texel, 0).r : (cones ? 1.0 - cone_cos * cone_cos : 1.0);
  float diffuse_visibility = visibility * material_occlusion;
  vec3 occlusion =
      (flags & 32u) != 0u ? multi_bounce_occlusion(diffuse_visibility, diffuse_color) : vec3(diffuse_visibility);
  vec3 irradiance_over_pi;  // of the open hemisphere, in the cone's shape when there is one
  if ((flags & 1u) != 0u)
    irradiance_over_pi = (cones ? sh_cone_irradiance(n, bent, cone_cos) : sh_irradiance(n)) / LG_SH_PI;
  else
    irradiance_over_pi = textureLod(irradiance_map, bent, 0.0).rgb;
  irradiance_over_pi *= intensity;
  if ((flags & 64u) != 0u) {
    vec4 volume = texelFetch(volume_tex, texel, 0);
    irradiance_over_pi = mix(irradiance_over_pi, volume.rgb / LG_SH_PI, clamp(volume.a, 0.0, 1.0));
  }
  // The diffuse gets what the specular lobe leaves at this view (brdf_energy.glsl).
  vec2 scale_bias = dfg_scale_bias(n_dot_v, roughness);
  vec3 diffuse = image_based_diffuse(diffuse_color, f0, scale_bias, irradiance_over_pi, occlusion);

  vec3 r = reflect(-v, n);
  float mips = float(textureQueryLevels(specular_map));
  vec3 reflected = intensity * textureLod(specular_map, sky ? -v : r, sky ? 0.0 : roughness * (mips - 1.0)).rgb;
  vec3 sky_color = direct + reflected;
  if ((flags & 256u) != 0u) {
    vec4 probes = texelFetch(probes_tex, texel, 0);
    reflected = mix(reflected, probes.rgb, clamp(probes.a, 0.0, 1.0));
  }
  if ((flags & 128u) != 0u) {
    vec4 ssr = texelFetch(ssr_tex, texel, 0);
    reflected = mix(reflected, ssr.rgb, clamp(ssr.a, 0.0, 1.0));
  }
  vec3 specular = split_sum_specular(reflected, f0, scale_bias);
  if ((flags & 16u) != 0u && cones)
    specular *= specular_occlusion_from_cone(n, r, bent, cone_cos, roughness);
  else if ((flags & 16u) != 0u && (flags & 4u) != 0u)
    specular *= specular_occlusion_from_ao(n_dot_v, visibility, roughness);
  if (material_occlusion < 1.0) specular *= specular_occlusion_from_ao(n_dot_v, material_occlusion, roughness);

  // One store for sky and surface: lavapipe runs both sides of a branch, so a store on each
  // side cost two a pixel.
  imageStore(color, texel, vec4(sky ? sky_color : direct + diffuse + specular, 1.0));
}
