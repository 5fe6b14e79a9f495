#version 460
#extension GL_GOOGLE_include_directive : require
// env.specular_prefilter, one dispatch per output mip: radiance prefiltered by GGX under the
// split-sum assumption N = V = R, sum of L(l) (n.l) / sum of (n.l) over `samples` half vectors
// drawn with density D (n.h) (a Hammersley set).
// `filtered` = 1 (the node) is filtered importance sampling (Krivanek and Colbert) with five
// corrections, each measured against the brute force (docs/bench/env, pisa.hdr at 256 samples,
// roughness 0.25 / 0.5 / 1: 2.2% / 1.7% / 3.8% with none, 1.2% / 1.3% / 1.3% with the first three,
// 0.58% / 0.45% / 0.63% with four, 0.59% / 0.39% / 0.58% with all five):
// - only half vectors with n.l > 0 are drawn (n.h > 1/sqrt(2): xi.x scaled into [0, 1 / (1 +
//   alpha^2)), the pdf grown by the same factor), so none is wasted below the horizon: half of
//   them were at roughness 1;
// - each sample is blurred over its solid angle 1 / (samples pdf), measured against the solid
//   angle of the environment's texels where it reads (4 m^3 / size^2, m the largest |l|
//   component: a face's centre texels subtend 5.2 times its corners'), not their mean;
// - that solid angle is capped near the horizon, which the integral excludes, smoothly: a hard
//   cap puts a kink in the blur that the next correction cannot see (1.5% / 1.0% / 1.1% with
//   the former hard cap);
// - each sample's weight takes out the bias the blur adds to the lobe, to second order
//   (blur_solid_angle). On pisa.hdr that bias was the error: the bright sky blurred into the
//   dark ground near the horizon of downward normals, +6% on some texels;
// - the blur is the node's own mip chain (prefilter_chain.comp: a [1 7 7 1] / 16 tent per level,
//   nearer a Gaussian than the input's 2x2 boxes) read at the lod whose blur has the variance the
//   weights assume (lod_for_variance). With the boxes the blur's shape limited the weights: an
//   emulation with an ideal Gaussian blur per sample reached 0.51% / 0.35% / 0.39%. Grace.hdr
//   went from 5.0% / 7.1% / 9.9% to 3.0% / 5.1% / 7.3%, the random environment from 0.39% /
//   0.50% / 0.30% to 0.31% / 0.47% / 0.27%.
// No lod bias: +1 (Krivanek and Colbert's) doubled to tripled the error before the weights; with
// them and the box chain +0.25 and -0.25 both raised pisa.hdr's error, with the tent chain -0.15
// did, and +0.15 lowered it at roughness 0.25 only (a double-precision emulation of this shader,
// within 2% of it). Roughness 0 reads the input along n at the mip whose texels match the
// output's. Non-finite radiance counts as 0.
// `filtered` = 0 is the benchmark's baseline, textbook GGX importance sampling: every sample
// from the whole distribution (those below the horizon dropped), the input's mip 0 only (bound
// as `chain`: one texture read in the loop serves both; with a read in each branch lavapipe ran
// the plain path nearly twice as long).
#include "nodes/common/shaders/brdf.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/cube_map.glsl"
#include "nodes/env/common/shaders/ggx_sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform samplerCube env;
layout(binding = 1, rgba16f) uniform writeonly image2DArray prefiltered_mip;
layout(binding = 2) uniform samplerCube chain;  // prefilter_chain.comp's (filtered), env (plain)
layout(push_constant) uniform Push {
  float roughness;  // perceptual; alpha = roughness^2
  uint samples;
  uint filtered;  // 1: filtered importance sampling (the node); 0: plain, mip 0 only
};

// Each sample is blurred with a variance (along each axis) of kBlur times its solid angle
// (lod_for_variance picks the lod that does so). Fitted in the emulation, pisa.hdr at 256
// samples: 0.3 gave 0.55% / 0.43% / 0.61%, 0.37 0.58% / 0.38% / 0.57%, 0.45 0.64% / 0.35% / 0.57%.
const float kBlur = 0.37;

// The solid angle a sample blurs over, and the factor on its weight that undoes the blur's bias.
// mu = n.l, pdf the sample's, d = (n.h)^2 (alpha^2 - 1) + 1 (pdf ~ 1 / d^2), b = dd / dmu.
// The solid angle is 1 / (samples pdf), capped (2-norm) by (mu / 2)^2, where the blur's
// footprint reaches 3/4 of the way to the horizon. A blur of variance k times the solid angle
// adds (k / 2) lap(g) to the lobe, g = solid angle * pdf * mu (Fokker-Planck), so the weight is
// scaled by 1 - (k / 2) solid_angle lap(g) / g, k = kBlur; g's derivatives along mu are analytic.

float blur_solid_angle(float mu, float d, float b, float pdf, out float weight_scale) {
  mu = max(mu, 1e-6);
  float u = 1.0 / mu, v = b / d;
  float ratio = min(4.0 / (float(samples) * pdf * mu * mu), 1e15);  // unclamped / horizon solid angle
  float r = ratio * ratio;
  float horizon_share = r / (1.0 + r);
  float solid_angle = 1.0 / (float(samples) * pdf * sqrt(1.0 + r));
  // G = g^-2 up to a constant: G'/G and G''/G along mu, and lap(g) / g from them.
  float dG = -2.0 * u * (1.0 + 2.0 * horizon_share) + 4.0 * v * horizon_share;
  float ddG = 6.0 * u * u + 12.0 * horizon_share * (3.0 * u - v) * (u - v);
  float lap_over_g = (1.0 - mu * mu) * (0.75 * dG * dG - 0.5 * ddG) + mu * dG;
  weight_scale = 1.0 - 0.5 * kBlur * solid_angle * lap_over_g;
  return solid_angle;
}

// The chain's lod whose blur has `variance` (along each axis, in mip-0 texels squared at the
// sample's direction). Level k blurs by 4^k / 6 (bilinear, on average over where it reads)
// plus the cascade's 1/2 (4^k - 1) / 3, V(k) = 4^k / 3 - 1/6, and lod k + f mixes levels k and
// k + 1, V(k) + f 4^k: with x = log4(3 variance + 1/2), k = floor(x), f = (4^fract(x) - 1) / 3.
// Below V(0) = 1/6 it reads mip 0 bilinearly.
float lod_for_variance(float variance) {
  float x = 0.5 * log2(3.0 * variance + 0.5);
  return x <= 0.0 ? 0.0 : floor(x) + (exp2(2.0 * fract(x)) - 1.0) / 3.0;
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
      float w = n_dot_l, lod = 0.0;
      if (filtered != 0u) {
        float d = h_local.z * h_local.z * (alpha * alpha - 1.0) + 1.0, scale;
        float solid_angle = blur_solid_angle(n_dot_l, d, 0.5 * (alpha * alpha - 1.0), pdf, scale);
        // Solid angle of the environment's texels at l: 4 m^3 / size^2, m the largest |l| component.
        float m = max(max(abs(l.x), abs(l.y)), abs(l.z));
        lod = lod_for_variance(kBlur * solid_angle * env_size * env_size / (4.0 * m * m * m));
        w *= scale;
      }
      sum += finite_or_zero(textureLod(chain, l, lod).rgb) * w;
      weight += w;
    }
    result = weight > 0.0 ? sum / weight : vec3(0.0);
  }
  imageStore(prefiltered_mip, ivec3(texel, face), vec4(result, 1.0));
}
