#version 460
#extension GL_GOOGLE_include_directive : require
// lighting.ssr's rays: for each pixel below the roughness cut-off, one reflection ray (the mirror
// direction; for glossy surfaces a GGX visible normal drawn from a per-pixel rotation of the R2
// sequence, a new point each frame) marched in screen space through the Hi-Z pyramid. The ray is
// a line in (pixel x, pixel y, device depth): with reversed-Z device depth near / linear depth,
// depth is affine along a projected line, so a cell's test is exact at its two ends. In front of
// a cell's nearest depth the ray skips the cell and climbs a level; otherwise it descends, and at
// level 0 it hits when it crossed the surface inside the pixel or lies behind it by less than
// `thickness` (linear depth). Surfaces that face along the ray (the ray passes under them: a
// grazing ray's own floor, the far side of a box) do not stop it. The hit reflects the lit image
// at its pixel: last frame's final image where the motion vectors find it, else this frame's
// `color`. Confidence: 0 for a miss (off screen, out of steps or length, thickness miss),
// otherwise the screen-edge fade times the roughness fade. At resolution_scale 1/k one invocation
// traces the ray of G-buffer pixel k * i for texel i of the smaller `reflections` grid.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"
#include "nodes/common/shaders/reprojection.glsl"
#include "nodes/env/common/shaders/ggx_sampling.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform CameraBlock { Camera camera; };
layout(binding = 1) uniform sampler2D hiz;  // nearest filtering, every mip
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D material_tex;  // r: perceptual roughness
layout(binding = 4) uniform sampler2D motion_tex;    // uv(now) - uv(last frame)
layout(binding = 5) uniform sampler2D color_tex;
layout(binding = 6) uniform sampler2D history_tex;  // bilinear; bound to color_tex when absent
layout(binding = 7, rgba16f) uniform writeonly image2D reflections;  // the grid of resolution_scale
layout(push_constant) uniform Push {
  uint max_steps;
  uint flags;  // 1: history usable
  uint frame;
  float max_roughness;
  float thickness;     // m, in linear depth
  float max_distance;  // m
  float edge_fade;     // fraction of the image
  float near_plane;    // m: linear depth = near_plane / device depth
  int k;               // 1 / resolution_scale
};

const float kNudge = 0.01;  // pixels past a cell's border, so the next lookup lands in the next cell

// A per-pixel offset in [0, 1)^2 (integer hash) rotating the R2 low-discrepancy sequence, whose
// point `frame` each frame takes: neighbours differ, and frames cover the lobe evenly.
vec2 sample_point(ivec2 texel) {
  uvec2 h = uvec2(texel) * uvec2(1664525u, 1013904223u);
  h ^= h.yx >> 16u;
  h *= 0x45d9f3bu;
  h ^= h.yx >> 16u;
  vec2 offset = vec2(h & 0xffffu) / 65536.0;
  return fract(offset + float(frame) * vec2(0.7548776662, 0.5698402910));
}

// The reflection direction at a surface with normal n seen along v (toward the eye).
vec3 reflection_direction(ivec2 texel, vec3 n, vec3 v, float roughness) {
  vec3 mirror = reflect(-v, n);
  float alpha = roughness * roughness;
  if (alpha < 1e-3) return mirror;
  vec3 t = normalize(abs(n.z) < 0.999 ? cross(vec3(0.0, 0.0, 1.0), n) : cross(vec3(1.0, 0.0, 0.0), n));
  vec3 b = cross(n, t);
  vec3 v_local = vec3(dot(v, t), dot(v, b), dot(v, n));
  vec3 h_local = sample_ggx_visible_normal(v_local, sample_point(texel), alpha);
  vec3 l = reflect(-v, h_local.x * t + h_local.y * b + h_local.z * n);
  return dot(l, n) > 0.0 ? l : mirror;  // below the surface: the mirror ray instead
}

// Where along the ray (origin o, direction d with its major axis 1 pixel a unit) it leaves the
// box of pixels from `lo` to `hi`.
float cell_exit(vec3 o, vec3 d, vec2 lo, vec2 hi) {
  vec2 border = mix(lo, hi, greaterThan(d.xy, vec2(0.0)));
  float tx = d.x != 0.0 ? (border.x - o.x) / d.x : 1e30;
  float ty = d.y != 0.0 ? (border.y - o.y) / d.y : 1e30;
  return min(tx, ty);
}

// The pixel the ray from s0 (pixels and device depth) along d first hits, or -1.
ivec2 march(vec3 s0, vec3 d, float t_end, vec3 l) {
  ivec2 size = textureSize(hiz, 0);
  int top = textureQueryLevels(hiz) - 1;
  // At resolution_scale 1/k the ray stands for a k x k block: start at the pyramid's level of
  // that size (the walk descends where it must), which saves the first climbs.
  int level = min(findMSB(k), top);
  float t = cell_exit(s0, d, floor(s0.xy), floor(s0.xy) + 1.0) + kNudge;  // out of the ray's own pixel
  ivec2 hit = ivec2(-1);
  for (uint i = 0u; i < max_steps && t < t_end && hit.x < 0; ++i) {
    vec3 q = s0 + d * t;
    if (any(lessThan(q.xy, vec2(0.0))) || any(greaterThanEqual(q.xy, vec2(size)))) break;  // off screen
    // Mip sizes by hand: lavapipe's textureSize() with a level that differs between the
    // invocations of one SIMD batch answers some of them with another invocation's level.
    ivec2 last = max(size >> level, ivec2(1)) - 1;
    ivec2 cell = min(ivec2(q.xy) >> level, last);
    // A level's last texel also covers what its odd-sized levels below left over: to the edge.
    vec2 hi = mix(vec2((cell + 1) << level), vec2(size), equal(cell, last));
    float t_exit = min(cell_exit(s0, d, vec2(cell << level), hi), t_end);
    float nearest = texelFetch(hiz, cell, level).r;
    if (min(q.z, s0.z + d.z * t_exit) > nearest) {  // in front of everything in the cell: skip it
      t = t_exit + kNudge;
      level = min(level + 1, top);
    } else if (level > 0) {  // something in the cell may be in the way: look closer
      --level;
    } else {
      // Level 0: the ray reaches or passes behind this pixel's surface. A hit when it crosses the
      // surface inside the pixel or lies behind it by less than `thickness`, on a front face.
      // The normal is fetched only for a candidate: most level-0 steps pass behind nothing.
      bool crossed = q.z >= nearest;
      bool thin = q.z > 0.0 && near_plane / q.z - near_plane / nearest <= thickness;
      if (nearest > 0.0 && (crossed || thin) && dot(decode_normal(texelFetch(normal_tex, cell, 0).rgb), l) < 0.0)
        hit = cell;
      t = t_exit + kNudge;  // otherwise: a thickness miss or a surface seen from behind, go on
    }
  }
  return hit;
}

// 1 inside the image, down to 0 over `edge_fade` of its width and height at the borders.
float edge_confidence(vec2 uv) {
  if (edge_fade <= 0.0) return 1.0;
  vec2 edge = min(uv, 1.0 - uv) / edge_fade;
  return clamp(min(edge.x, edge.y), 0.0, 1.0);
}

vec3 hit_radiance(ivec2 hit) {
  vec3 c = texelFetch(color_tex, hit, 0).rgb;
  if ((flags & 1u) != 0u) {
    vec2 previous;
    if (reproject((vec2(hit) + 0.5) * camera.viewport.zw, texelFetch(motion_tex, hit, 0).rg, previous))
      c = textureLod(history_tex, previous, 0.0).rgb;
  }
  return min(finite_or_zero(c), vec3(65504.0));  // the largest half float: no Inf in the output
}

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(low, imageSize(reflections)))) return;
  ivec2 size = textureSize(hiz, 0);
  ivec2 texel = upsample_source_texel(low, k, size);
  float depth = texelFetch(hiz, texel, 0).r;  // NaN already made 0 by the pyramid
  float roughness = texelFetch(material_tex, texel, 0).r;
  float roughness_fade = clamp((max_roughness - roughness) / (0.25 * max_roughness), 0.0, 1.0);
  if (depth <= 0.0 || !(roughness_fade > 0.0)) {  // the sky, or too rough
    imageStore(reflections, low, vec4(0.0));
    return;
  }
  vec3 p = world_position(camera, texel, depth);
  vec3 eye = camera.position.xyz;
  vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
  vec3 v = normalize(eye - p);
  vec3 l = reflection_direction(texel, n, v, roughness);

  // The ray's ends in clip space, the far one pulled in to stay in front of the near plane
  // (clip w is linear depth and affine along the ray).
  vec4 c0 = camera.view_projection * vec4(p, 1.0);
  float len = max_distance;
  vec4 c1 = camera.view_projection * vec4(p + l * len, 1.0);
  if (c1.w < near_plane) {
    len *= (c0.w - near_plane) / max(c0.w - c1.w, 1e-30);
    c1 = camera.view_projection * vec4(p + l * len, 1.0);
  }
  vec3 s0 = vec3((c0.xy / c0.w * 0.5 + 0.5) * vec2(size), c0.z / c0.w);
  vec3 s1 = vec3((c1.xy / max(c1.w, 1e-30) * 0.5 + 0.5) * vec2(size), c1.z / max(c1.w, 1e-30));
  vec3 delta = s1 - s0;
  float span = max(abs(delta.x), abs(delta.y));
  vec4 result = vec4(0.0);
  if (span >= 1.0 && all(equal(finite_or_zero(delta), delta))) {  // it leaves its own pixel
    ivec2 hit = march(s0, delta / span, span, l);
    if (hit.x >= 0)
      result = vec4(hit_radiance(hit), edge_confidence((vec2(hit) + 0.5) / vec2(size)) * roughness_fade);
  }
  imageStore(reflections, low, result);
}
