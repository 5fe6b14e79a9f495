#version 460
#extension GL_GOOGLE_include_directive : require
// env.load, mip 0: each cube texel the mean of supersample^2 bilinear samples of the
// equirectangular image spread evenly over the texel (nodes/env/common/equirect.h states the
// mapping; the bilinear wraps around in u and clamps at the poles, as the CPU reference does).
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D equirect;  // fetched, not filtered by the sampler
layout(binding = 1, rgba16f) uniform writeonly image2DArray cube_mip;
layout(push_constant) uniform Push {
  int supersample;
};

const float kPi = 3.14159265358979;

vec3 fetch(ivec2 p, ivec2 size) {
  p.x = ((p.x % size.x) + size.x) % size.x;
  p.y = clamp(p.y, 0, size.y - 1);
  return texelFetch(equirect, p, 0).rgb;
}

vec3 sample_equirect(vec3 d) {
  ivec2 size = textureSize(equirect, 0);
  vec2 uv = vec2(0.5 + atan(d.x, -d.z) / (2.0 * kPi), acos(clamp(d.y, -1.0, 1.0)) / kPi);
  vec2 p = vec2(uv.x * float(size.x) - 0.5, clamp(uv.y * float(size.y) - 0.5, 0.0, float(size.y - 1)));
  ivec2 p0 = ivec2(floor(p));
  vec2 f = p - vec2(p0);
  return mix(mix(fetch(p0, size), fetch(p0 + ivec2(1, 0), size), f.x),
             mix(fetch(p0 + ivec2(0, 1), size), fetch(p0 + ivec2(1, 1), size), f.x), f.y);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(cube_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec3 sum = vec3(0.0);
  for (int b = 0; b < supersample; ++b)
    for (int a = 0; a < supersample; ++a)
      sum += sample_equirect(cube_direction(face, (vec2(texel) + (vec2(a, b) + 0.5) / float(supersample)) / float(size)));
  imageStore(cube_mip, ivec3(texel, face), vec4(sum / float(supersample * supersample), 1.0));
}
