#version 460
#extension GL_GOOGLE_include_directive : require
// Classic normal-oriented hemisphere SSAO, the baseline GTAO is measured against: cosine-
// distributed points within the radius around the surface, each projected into the depth
// buffer; a point counts as occluded when the buffer's surface there lies in front of it by
// more than the bias and within the radius (a range check against far-away occluders). The
// unoccluded fraction estimates cosine-weighted visibility, so an open plane gives 1.
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/occlusion/ssao/shaders/ssao_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D gbuffer_depth;
layout(binding = 2) uniform sampler2D gbuffer_normal;
layout(binding = 3, r8) uniform writeonly image2D noisy;

const float PI = 3.14159265358979;

float hash(uvec2 p, uint i) {
  uint h = p.x * 1973u + p.y * 9277u + i * 26699u;
  h = (h ^ (h >> 13u)) * 0x5bd1e995u;
  return float((h ^ (h >> 15u)) & 0xffffffu) / 16777216.0;
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(noisy);
  if (any(greaterThanEqual(texel, size))) return;
  float depth = texelFetch(gbuffer_depth, texel, 0).r;
  if (!(depth > 0.0)) {
    imageStore(noisy, texel, vec4(1.0));
    return;
  }
  vec3 p = world_position(camera, texel, depth);
  vec3 n = decode_normal(texelFetch(gbuffer_normal, texel, 0).rgb);
  vec3 t = normalize(abs(n.y) < 0.99 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(n, t);
  float radius = settings.x, bias = settings.y;
  uint samples = counts.x;
  float rotation = 2.0 * PI * hash(uvec2(texel), 0u);
  float visible = 0.0;
  for (uint i = 0u; i < samples; ++i) {
    // Stratified cosine-weighted direction (Malley: a disc lifted to the hemisphere), rotated
    // per pixel, at a distance that clusters toward the centre.
    float u = (float(i) + hash(uvec2(texel), i + 1u)) / float(samples);
    float phi = rotation + 2.39996323 * float(i);  // golden angle
    float r = sqrt(u);
    vec3 dir = t * (r * cos(phi)) + b * (r * sin(phi)) + n * sqrt(max(1.0 - u, 0.0));
    float scale = mix(0.1, 1.0, hash(uvec2(texel), i + 101u));
    vec3 s = p + dir * (radius * scale);
    vec4 clip = camera.view_projection * vec4(s, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
      visible += 1.0;  // off screen: nothing known occludes it
      continue;
    }
    float scene_z = linear_depth(texelFetch(gbuffer_depth, ivec2(uv * vec2(size)), 0).r);
    float sample_z = clip.w;
    bool in_front = scene_z < sample_z - bias;
    bool in_range = sample_z - scene_z < radius;
    visible += in_front && in_range ? 0.0 : 1.0;
  }
  imageStore(noisy, texel, vec4(samples > 0u ? visible / float(samples) : 1.0));
}
