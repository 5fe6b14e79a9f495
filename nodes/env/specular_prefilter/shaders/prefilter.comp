#version 460
#extension GL_GOOGLE_include_directive : require
// env.specular_prefilter, one dispatch per output mip: radiance prefiltered by GGX under the
// split-sum assumption N = V = R, sum of L(l) (n.l) / sum of (n.l) over `samples` half vectors
// drawn with density D (n.h) (a Hammersley set).
// `filtered` = 1 (the node) is filtered importance sampling (Krivanek and Colbert) with three
// corrections, each measured against the brute force (docs/bench/env, pisa.hdr at 256 samples,
// roughness 0.25 / 0.5 / 1: 2.2% / 1.7% / 3.8% before, 1.2% / 1.3% / 1.3% after):
// - only half vectors with n.l > 0 are drawn (n.h > 1/sqrt(2): xi.x scaled into [0, 1 / (1 +
//   alpha^2)), the pdf grown by the same factor), so none is wasted below the horizon: half of
//   them were at roughness 1;
// - each sample reads the mip whose texels match its solid angle 1 / (samples pdf), against the
//   solid angle of the environment's texels where it reads (4 m^3 / size^2, m the largest |l|
//   component: a face's centre texels subtend 5.2 times its corners'), not their mean;
// - that mip is capped where its trilinear footprint (1.5 texels either side) would reach below
//   the horizon, which the integral excludes.
// No lod bias: +1 (Krivanek and Colbert's) doubled to tripled the error; -0.5 lowers it on pisa.hdr and
// raises it on grace.hdr and on the random environment. Roughness 0 reads the environment along
// n at the mip whose texels match the output's. Non-finite radiance counts as 0.
// `filtered` = 0 is the benchmark's baseline, textbook GGX importance sampling: every sample
// from the whole distribution (those below the horizon dropped), mip 0 only.
#include "nodes/common/shaders/brdf.glsl"
#include "nodes/env/common/shaders/cube_map.glsl"
#include "nodes/env/common/shaders/ggx_sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform samplerCube env;
layout(binding = 1, rgba16f) uniform writeonly image2DArray prefiltered_mip;
layout(push_constant) uniform Push {
  float roughness;  // perceptual; alpha = roughness^2
  uint samples;
  uint filtered;  // 1: filtered importance sampling (the node); 0: plain, mip 0 only
};

vec3 finite_or_zero(vec3 c) {
  return any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : c;
}

// The mip of `env` (edge `env_size`) whose texels around direction l match `solid_angle`,
// capped where the trilinear footprint would cross the horizon of n (n_dot_l = n.l > 0).
float footprint_lod(vec3 l, float n_dot_l, float solid_angle, float env_size) {
  float m = max(max(abs(l.x), abs(l.y)), abs(l.z));
  float texel_solid_angle = 4.0 * m * m * m / (env_size * env_size);
  float lod = 0.5 * log2(solid_angle / texel_solid_angle);
  float horizon_lod = log2(n_dot_l * inversesqrt(texel_solid_angle) / 1.5);
  return max(min(lod, horizon_lod), 0.0);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(prefiltered_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec3 n = cube_direction(face, (vec2(texel) + 0.5) / float(size));
  float env_size = float(textureSize(env, 0).x);
  float alpha = roughness * roughness;
  vec3 result;
  if (alpha == 0.0) {
    result = finite_or_zero(textureLod(env, n, max(log2(env_size / float(size)), 0.0)).rgb);
  } else {
    vec3 t = normalize(cross(abs(n.y) < 0.999 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), n));
    vec3 b = cross(n, t);
    // The share of D (n.h) with n.h > 1/sqrt(2), where l = reflect(-n, h) is above the horizon.
    float above_horizon = filtered != 0u ? 1.0 / (1.0 + alpha * alpha) : 1.0;
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < samples; ++i) {
      vec2 xi = hammersley(i, samples);
      vec3 h_local = sample_ggx_half_vector(vec2(xi.x * above_horizon, xi.y), alpha);
      vec3 h = h_local.x * t + h_local.y * b + h_local.z * n;
      vec3 l = 2.0 * h_local.z * h - n;
      float n_dot_l = dot(n, l);
      if (n_dot_l <= 0.0) continue;
      // pdf(l) = D (n.h) / (4 v.h) = D / 4 with v = n, over the drawn share of the distribution.
      float pdf = ggx_distribution(h_local.z, alpha) * 0.25 / above_horizon;
      float lod = filtered != 0u ? footprint_lod(l, n_dot_l, 1.0 / (float(samples) * pdf), env_size) : 0.0;
      sum += finite_or_zero(textureLod(env, l, lod).rgb) * n_dot_l;
      weight += n_dot_l;
    }
    result = weight > 0.0 ? sum / weight : vec3(0.0);
  }
  imageStore(prefiltered_mip, ivec3(texel, face), vec4(result, 1.0));
}
