// What the GTAO passes share (gtao_kernel.cpp fills it, std140): the camera's projection in
// the form view-space reconstruction needs, and the quality settings. View space is right
// handed, the camera looks down -z; "linear depth" is the distance along -z.
#ifndef LG_GTAO_CONSTANTS_GLSL
#define LG_GTAO_CONSTANTS_GLSL

#include "nodes/common/shaders/joint_upsample.glsl"

layout(std140, binding = 0) uniform Constants {
  mat4 view_from_world;  // rotates world normals into view space (no translation used)
  mat4 world_from_view;
  vec4 unproject;        // 1 / P[0][0], 1 / P[1][1], P[2][0], P[2][1]: ndc -> view x, y per unit depth
  vec4 viewport;         // the G-buffer's width, height, 1 / width, 1 / height
  vec4 search;           // radius (m), pixels per metre at unit depth, z stretch of the falloff, max radius (px)
  uvec4 counts;          // unused, unused, frame index, history usable (0 or 1)
  vec4 blend;            // temporal weight of the history, near plane, k = 1 / resolution_scale, unused
};

// The G-buffer pixel that texel `texel` of the horizon grid stands for: the grid is the
// G-buffer's own at resolution_scale 1 and 1/k of it below, where the horizons and the denoiser
// run before upsample.comp brings them back (joint_upsample.glsl's rule).
ivec2 grid_pixel(ivec2 texel) {
  return upsample_source_texel(texel, int(blend.z), ivec2(viewport.xy));
}

// Reversed-Z infinite projection: device depth = near / linear depth.
float linear_depth(float device_depth) {
  return device_depth > 0.0 ? blend.y / device_depth : 1e8;
}

// The view-space point at pixel centre `uv` (0..1 across the image) with linear depth `z`.
vec3 view_position(vec2 uv, float z) {
  vec2 ndc = uv * 2.0 - 1.0;
  return vec3((ndc.x + unproject.z) * unproject.x, (ndc.y + unproject.w) * unproject.y, -1.0) * z;
}

#endif
