#version 460
#extension GL_GOOGLE_include_directive : require
// lighting.ssr's resolve: glossy pixels (roughness above kGlossy) reuse their 3x3 neighbours' hits,
// weighted by confidence and by how alike the neighbour's depth and normal are, so one ray a pixel
// covers more of the lobe; then last frame's result, fetched where the motion vectors say this
// surface was and clamped to this frame's neighbourhood (a disoccluded or changed pixel cannot
// keep stale values), is blended in. Both work on radiance premultiplied by confidence, which is
// what lighting.ibl's mix adds up: averaging (rgb a, a) and dividing back keeps a hit's weight
// proportional to its confidence. Pixels the trace skipped (the sky, too rough) write 0 at once.
// At resolution_scale 1/k it runs on the trace's grid, texel i standing for G-buffer pixel k * i;
// the history it blends is the full-resolution output of the last frame.
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"
#include "nodes/common/shaders/reprojection.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D raw;  // the trace's rgb and confidence, on its grid
layout(binding = 1) uniform sampler2D hiz;  // level 0: device depth
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D material_tex;
layout(binding = 4) uniform sampler2D motion_tex;
layout(binding = 5) uniform sampler2D history;  // bilinear; bound to `raw` when absent
layout(binding = 6, rgba16f) uniform writeonly image2D reflections;  // the trace's grid
layout(push_constant) uniform Push {
  uint flags;  // 1: history usable, 2: spatial reuse
  float temporal_blend;
  float max_roughness;
  int k;  // 1 / resolution_scale
};

const float kGlossy = 0.1;  // perceptual roughness above which neighbours' hits are reused

vec4 premultiplied(vec4 c) {
  return vec4(c.rgb * c.a, c.a);
}

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(reflections), full_size = textureSize(hiz, 0);
  if (any(greaterThanEqual(low, size))) return;
  ivec2 texel = upsample_source_texel(low, k, full_size);
  float depth = texelFetch(hiz, texel, 0).r;
  float roughness = texelFetch(material_tex, texel, 0).r;
  if (depth <= 0.0 || !(roughness < max_roughness)) {  // as the trace: nothing was traced here
    imageStore(reflections, low, vec4(0.0));
    return;
  }
  // The neighbourhood's range, which also bounds last frame's result: where no neighbour has a
  // hit, the output is 0 whatever the history held, and nothing more needs reading. The taps are
  // fetched again below rather than kept in an array: lavapipe keeps such an array in memory.
  vec4 lo = vec4(1e30), hi = vec4(-1e30);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      vec4 tap = premultiplied(texelFetch(raw, clamp(low + ivec2(dx, dy), ivec2(0), size - 1), 0));
      lo = min(lo, tap);
      hi = max(hi, tap);
    }
  if (!(hi.a > 0.0)) {
    imageStore(reflections, low, vec4(0.0));
    return;
  }
  vec4 result = premultiplied(texelFetch(raw, low, 0));
  if ((flags & 2u) != 0u && roughness > kGlossy) {
    vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        ivec2 neighbour = clamp(low + ivec2(dx, dy), ivec2(0), size - 1);
        ivec2 source = upsample_source_texel(neighbour, k, full_size);
        // Alike surfaces only: device depth within 5% (relative, as it is near / distance),
        // normals within about 35 degrees (cosine^8 above 0.03).
        float d = texelFetch(hiz, source, 0).r;
        float w = clamp(1.0 - abs(d - depth) / (0.05 * depth), 0.0, 1.0) *
                  pow(max(dot(n, decode_normal(texelFetch(normal_tex, source, 0).rgb)), 0.0), 8.0);
        sum += w * premultiplied(texelFetch(raw, neighbour, 0));
        weight += w;
      }
    if (weight > 0.0) result = sum / weight;
  }
  if ((flags & 1u) != 0u && temporal_blend > 0.0) {
    vec2 uv = (vec2(texel) + 0.5) / vec2(full_size);
    vec2 previous;
    if (reproject(uv, texelFetch(motion_tex, texel, 0).rg, previous)) {
      vec4 past = clamp(premultiplied(textureLod(history, previous, 0.0)), lo, hi);
      result = mix(result, past, temporal_blend);
    }
  }
  result = vec4(finite_or_zero(result.rgb), clamp(result.a, 0.0, 1.0));
  vec3 radiance = result.a > 0.0 ? min(result.rgb / result.a, vec3(65504.0)) : vec3(0.0);  // no Inf in half floats
  imageStore(reflections, low, vec4(radiance, result.a));
}
