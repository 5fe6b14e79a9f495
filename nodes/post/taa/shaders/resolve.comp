#version 460
#extension GL_GOOGLE_include_directive : require
// post.taa's resolve: this frame's pixel (rendered with the jittered camera) blended with last
// frame's accumulation, fetched where the motion vectors say this surface was. The history is
// rejected where it falls outside the image, where the depth it was accumulated at is not where
// this surface was (disocclusion), or where it is not finite; otherwise it is clipped to this
// frame's 3x3 neighbourhood (variance clipping in YCoCg: the box mean +- clip_sigma standard
// deviations, within the neighbourhood's min and max) before the blend. The motion and the depth
// are taken at the 3x3 neighbourhood's closest pixel, so edges reproject with the foreground
// and a silhouette's depth does not flip with the jitter. Non-finite input pixels are left out
// of the neighbourhood and never reach the output.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/reprojection.glsl"
#include "nodes/post/taa/shaders/taa_color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(binding = 1) uniform sampler2D color;    // nearest
layout(binding = 2) uniform sampler2D depth;    // nearest; reversed Z, 0 is the sky
layout(binding = 3) uniform sampler2D motion;   // nearest; uv now - uv last frame, no jitter
layout(binding = 4) uniform sampler2D history;  // bilinear; rgb radiance, a depth; bound to color when absent
layout(binding = 5, rgba16f) uniform writeonly image2D accumulated;
layout(push_constant) uniform Push {
  float feedback;
  float clip_sigma;
  float depth_tolerance;
  uint use_history;  // 0: first frame, camera cut or unlinked history
};

// Moves `h` toward the box's centre until it is inside the box (clipping keeps the history's
// hue better than clamping each axis).
vec3 clip_to_box(vec3 h, vec3 lo, vec3 hi) {
  vec3 center = 0.5 * (hi + lo), half_size = 0.5 * (hi - lo) + 1e-6;
  vec3 v = h - center;
  vec3 a = abs(v / half_size);
  float m = max(a.x, max(a.y, a.z));
  return m > 1.0 ? center + v / m : h;
}

// The history at `uv` through a Catmull-Rom filter, from 9 bilinear taps (Jimenez's arrangement:
// the middle two weights of each axis share one tap). Bilinear alone blurs the history a little
// more every frame the camera moves by a fraction of a pixel; at a texel's centre this is that
// texel exactly. The negative lobes may undershoot: the clip that follows bounds the result.
vec3 history_catmull_rom(vec2 uv, vec2 size) {
  vec2 position = uv * size;
  vec2 center = floor(position - 0.5) + 0.5;
  vec2 f = position - center;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 taps[3] = vec2[]((center - 1.0) / size, (center + w2 / w12) / size, (center + 2.0) / size);
  vec2 weights[3] = vec2[](w0, w12, w3);
  vec3 sum = vec3(0.0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      sum += textureLod(history, vec2(taps[x].x, taps[y].y), 0.0).rgb * (weights[x].x * weights[y].y);
  return sum;
}

// Where this frame's surface at `texel` (depth d > 0) was in last frame's depth: its world
// position through last frame's camera. The sky (d = 0) stays at 0.
float previous_depth(ivec2 texel, float d) {
  if (d <= 0.0) return 0.0;
  vec4 p = camera.previous_view_projection * vec4(world_position(camera, texel, d), 1.0);
  return p.w > 0.0 ? p.z / p.w : -1.0;  // behind last frame's camera: matches nothing
}

void main() {
  ivec2 size = imageSize(accumulated);
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;

  vec3 sum = vec3(0.0), sum_sq = vec3(0.0), lo = vec3(1e30), hi = vec3(-1e30), center = vec3(0.0);
  float count = 0.0, closest = -1.0, farthest = 2.0;
  bool center_usable = false;
  ivec2 closest_texel = texel;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      ivec2 t = clamp(texel + ivec2(x, y), ivec2(0), size - 1);
      float d = texelFetch(depth, t, 0).r;
      farthest = min(farthest, d);
      if (d > closest) {
        closest = d;
        closest_texel = t;
      }
      vec3 c = texelFetch(color, t, 0).rgb;
      if (!usable(c)) continue;
      vec3 q = rgb_to_ycocg(clamp(c, 0.0, kHalfMax));
      sum += q;
      sum_sq += q * q;
      lo = min(lo, q);
      hi = max(hi, q);
      count += 1.0;
      if (x == 0 && y == 0) {
        center = q;
        center_usable = true;
      }
    }
  vec3 mean = count > 0.0 ? sum / count : vec3(0.0);
  vec3 sigma = sqrt(max(sum_sq / max(count, 1.0) - mean * mean, 0.0));
  // A non-finite pixel takes its neighbourhood's mean (0 when all nine are broken).
  vec3 current = center_usable ? center : mean;

  vec3 result = current;
  vec2 uv = (vec2(texel) + 0.5) * camera.viewport.zw;
  vec2 previous_uv;
  bool inside = reproject(uv, texelFetch(motion, closest_texel, 0).rg, previous_uv);
  if (use_history != 0u && count > 0.0 && inside) {
    vec3 past = history_catmull_rom(previous_uv, vec2(size));
    float seen = texelFetch(history, clamp(ivec2(previous_uv * vec2(size)), ivec2(0), size - 1), 0).a;
    float expected = previous_depth(closest_texel, closest);
    // Within the tolerance, widened by the neighbourhood's own depth range: the jitter moves the
    // closest depth by up to that much on a still surface (a slope seen at a grazing angle).
    bool same_surface = abs(expected - seen) <= depth_tolerance * max(max(expected, seen), 1e-7) + (closest - farthest);
    if (same_surface && usable(past)) {
      vec3 box_lo = max(lo, mean - clip_sigma * sigma), box_hi = min(hi, mean + clip_sigma * sigma);
      vec3 h = clip_to_box(rgb_to_ycocg(clamp(past, 0.0, kHalfMax)), box_lo, box_hi);
      result = mix(current, h, feedback);
    }
  }
  imageStore(accumulated, texel, vec4(clamp(ycocg_to_rgb(result), 0.0, kHalfMax), closest));
}
