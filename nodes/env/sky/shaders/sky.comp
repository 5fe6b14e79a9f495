#version 460
#extension GL_GOOGLE_include_directive : require
// env.sky, one dispatch per mip: each texel is the sky (nodes/env/sky/sky_model.h) averaged over
// the texel (subsamples^2 points weighted by the Jacobian), plus the sun disk's energy that falls
// in the texel (64 points spread evenly over the disk, each carrying 1/64 of its radiance times
// its solid angle) divided by the texel's solid angle. So every mip holds the same integral of
// radiance, the sun's included, however small the disk is against a texel.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform writeonly image2DArray cube_mip;
layout(push_constant) uniform Push {
  vec4 sun;           // xyz: towards the sun; w: sun radiance x disk solid angle / kSunPoints
  vec4 sky_sun;       // xyz: the sun lighting the sky (at or above the horizon); w: disk angular radius
  vec4 perez_lum;     // A..D of luminance Y
  vec4 perez_x;       // A..D of chromaticity x
  vec4 perez_y;       // A..D of chromaticity y
  vec4 perez_e;       // E of Y, x, y
  vec4 ground;        // rgb: radiance below the horizon
  vec3 zenith_scale;  // zenith value / F(0, theta_sun) of Y, x, y
  int subsamples;     // per axis
};

const int kSunPoints = 64;
const float kHalfMax = 65504.0;  // larger texels would be Inf in rgba16f: they clamp

float perez(vec4 abcd, float e, float cos_theta, float gamma) {
  float cos_gamma = cos(gamma);
  return (1.0 + abcd.x * exp(abcd.y / max(cos_theta, 0.01))) * (1.0 + abcd.z * exp(abcd.w * gamma) + e * cos_gamma * cos_gamma);
}

vec3 sky(vec3 d) {
  if (d.y < 0.0) return ground.rgb;
  float gamma = acos(clamp(dot(d, sky_sun.xyz), -1.0, 1.0));
  float lum = zenith_scale.x * perez(perez_lum, perez_e.x, d.y, gamma);
  float x = zenith_scale.y * perez(perez_x, perez_e.y, d.y, gamma);
  float y = zenith_scale.z * perez(perez_y, perez_e.z, d.y, gamma);
  vec3 xyz = vec3(x / y * lum, lum, (1.0 - x - y) / y * lum);
  mat3 to_rec709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314, 0.0415560, 1.0572252);
  return max(to_rec709 * xyz, vec3(0.0));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(cube_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;

  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int b = 0; b < subsamples; ++b)
    for (int a = 0; a < subsamples; ++a) {
      vec2 uv = (vec2(texel) + (vec2(a, b) + 0.5) / float(subsamples)) / float(size);
      float jacobian = cube_jacobian(uv * 2.0 - 1.0);
      sum += jacobian * sky(cube_direction(face, uv));
      weight += jacobian;
    }
  vec3 radiance = sum / weight;

  vec3 axis = sun.xyz;
  vec3 t = normalize(cross(abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), axis));
  vec3 b = cross(axis, t);
  int hits = 0;
  for (int k = 0; k < kSunPoints; ++k) {
    float r = sky_sun.w * sqrt((float(k) + 0.5) / float(kSunPoints));
    float phi = 2.39996323 * float(k);  // the golden angle: a sunflower pattern
    vec3 p = cos(r) * axis + sin(r) * (cos(phi) * t + sin(phi) * b);
    if (p.y < 0.0) continue;  // behind the ground
    int hit_face;
    vec2 uv = cube_face_uv(p, hit_face);
    if (hit_face == face && all(equal(min(ivec2(uv * float(size)), ivec2(size - 1)), texel))) ++hits;
  }
  radiance += sun.w * float(hits) / cube_texel_solid_angle(texel, size);
  imageStore(cube_mip, ivec3(texel, face), vec4(min(radiance, vec3(kHalfMax)), 1.0));
}
