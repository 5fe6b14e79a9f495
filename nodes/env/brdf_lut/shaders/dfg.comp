#version 460
#extension GL_GOOGLE_include_directive : require
// env.brdf_lut: the split-sum DFG table. Texel (i, j) holds, for n.v = i / (size - 1) (at least
// 1e-4) and perceptual roughness j / (size - 1), the scale A (R) and bias B (G) with
// integral of f_spec (n.l) = F0 A + B under Schlick's Fresnel, for the GGX distribution and the
// height-correlated Smith visibility of nodes/common/shaders/brdf.glsl; by sampling the visible
// normals at `samples` points of a Hammersley set (the estimator G2 / G1(v) is smooth and at
// most 1, so grazing views converge too; sampling D (n.h) was 4% off there at 512 samples). The sum A + B is the single-scattering
// albedo E(n.v, roughness) that lighting.ibl's multiple-scattering compensation is made from.
#include "nodes/common/shaders/brdf.glsl"
#include "nodes/env/common/shaders/ggx_sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rg16f) uniform writeonly image2D lut;
layout(push_constant) uniform Push {
  uint samples;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(lut);
  if (any(greaterThanEqual(texel, size))) return;
  vec2 at = vec2(texel) / vec2(max(size - 1, ivec2(1)));
  float n_dot_v = max(at.x, 1e-3);
  float alpha = at.y * at.y;
  vec3 v = vec3(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
  float lambda_v = 0.5 * (sqrt(alpha * alpha + (1.0 - alpha * alpha) * n_dot_v * n_dot_v) / n_dot_v - 1.0);
  vec2 scale_bias = vec2(0.0);
  for (uint i = 0u; i < samples; ++i) {
    vec3 h = sample_ggx_visible_normal(v, hammersley(i, samples), alpha);
    float v_dot_h = dot(v, h);
    vec3 l = 2.0 * v_dot_h * h - v;
    if (l.z <= 0.0 || v_dot_h <= 0.0) continue;
    // f (n.l) / pdf(l) with pdf = G1(v) D / (4 n.v): G2 / G1(v) = 4 (n.l)(n.v) V (1 + Lambda(v)).
    float weight = 4.0 * l.z * n_dot_v * smith_visibility(n_dot_v, l.z, alpha) * (1.0 + lambda_v);
    float fc = pow(1.0 - v_dot_h, 5.0);
    scale_bias += weight * vec2(1.0 - fc, fc);
  }
  imageStore(lut, texel, vec4(scale_bias / float(samples), 0.0, 0.0));
}
