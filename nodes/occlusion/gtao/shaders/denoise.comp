#version 460
#extension GL_GOOGLE_include_directive : require
// A depth-aware 3x3 blur of the raw occlusion (weights from the packed edges, so occlusion
// does not bleed across silhouettes), then temporal accumulation: last frame's result is
// fetched where the motion vector says this surface was, clamped to this frame's neighbourhood
// (history rejection: a disoccluded or changed pixel cannot keep stale values) and blended.
#include "nodes/common/shaders/reprojection.glsl"
#include "nodes/occlusion/gtao/shaders/gtao_constants.glsl"

// One invocation a 2x2 quad of pixels, 8x8 invocations a 16x16 tile: the quad's four 3x3
// neighbourhoods share one 4x4 block of fetches (16 rather than 36), and lavapipe pays for every
// invocation.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D noisy;  // below resolution_scale 1, horizons.comp's surface
layout(binding = 2) uniform sampler2D edges;
layout(binding = 3) uniform sampler2D motion;
layout(binding = 4) uniform sampler2D history;  // bilinear; bound to `noisy` when absent
// 1 / resolution_scale, fixed when the pipeline is made: lavapipe runs both sides of a branch
// on a uniform (masked), so the store this scale does not make must not be in its pipeline.
layout(constant_id = 0) const int grid_divisor = 1;

// On the horizon grid, as noisy and edges: ao at resolution_scale 1 (the node's output), else
// ao_guide (ao_guide.glsl: the texel's surface carried over from noisy), the other one bound but
// not written.
layout(binding = 5, r8) uniform writeonly image2D ao;
layout(binding = 6, rgba16f) uniform writeonly image2D ao_guide;

vec4 unpack_edges(float packed) {
  uint bits = uint(round(packed * 255.0));
  return vec4((bits >> 6) & 3u, (bits >> 4) & 3u, (bits >> 2) & 3u, bits & 3u) / 3.0;
}

// Pixel `texel` of the quad whose 4x4 block of raw occlusion (the quad and its one-pixel ring)
// is `block`; `corner` is the pixel's place in the quad (0 or 1 each way), `own` its noisy texel.
void denoise_pixel(ivec2 texel, ivec2 corner, float block[4][4], vec4 own) {
  vec4 e = unpack_edges(texelFetch(edges, texel, 0).r);  // left, right, top, bottom
  float sum = 0.0, weight = 0.0, lo = 1.0, hi = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      float wx = x < 0 ? e.x : x > 0 ? e.y : 1.0;
      float wy = y < 0 ? e.z : y > 0 ? e.w : 1.0;
      float w = wx * wy * (x == 0 && y == 0 ? 1.5 : 1.0);
      float v = block[corner.y + y + 1][corner.x + x + 1];
      sum += w * v;
      weight += w;
      if (w > 0.0) {
        lo = min(lo, v);
        hi = max(hi, v);
      }
    }
  float current = sum / weight;
  float result = current;
  if (counts.w != 0u && blend.x > 0.0) {
    // The history is at full resolution: read where this texel's G-buffer pixel was.
    ivec2 pixel = grid_pixel(texel);
    vec2 uv = (vec2(pixel) + 0.5) * viewport.zw;
    vec2 previous_uv;
    if (reproject(uv, texelFetch(motion, pixel, 0).rg, previous_uv)) {
      float past = clamp(textureLod(history, previous_uv, 0.0).r, lo, hi);
      result = mix(current, past, blend.x);
    }
  }
  if (grid_divisor > 1)
    imageStore(ao_guide, texel, vec4(result, own.yzw));
  else
    imageStore(ao, texel, vec4(result));
}

void main() {
  ivec2 size = textureSize(noisy, 0);
  ivec2 origin = ivec2(gl_GlobalInvocationID.xy) * 2;
  if (any(greaterThanEqual(origin, size))) return;
  float block[4][4];
  vec4 quad[2][2];  // the quad's own texels, whole
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      vec4 v = texelFetch(noisy, clamp(origin + ivec2(x - 1, y - 1), ivec2(0), size - 1), 0);
      block[y][x] = v.r;
      if (x >= 1 && x <= 2 && y >= 1 && y <= 2) quad[y - 1][x - 1] = v;
    }
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      if (all(lessThan(origin + ivec2(x, y), size)))
        denoise_pixel(origin + ivec2(x, y), ivec2(x, y), block, quad[y][x]);
}
