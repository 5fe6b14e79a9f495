// The camera as every pass sees it (nodes/common/camera_constants.h fills it, std140). Depth is
// reversed Z with an infinite far plane: 1 at the near plane, 0 at infinity (the sky).
#ifndef LG_CAMERA_GLSL
#define LG_CAMERA_GLSL

struct Camera {
  mat4 view_projection;
  mat4 inverse_view_projection;
  mat4 previous_view_projection;
  vec4 position;  // xyz: the eye in world space
  vec4 viewport;  // width, height, 1 / width, 1 / height of the pass's target
  vec4 jitter;    // xy: the sub-pixel offset in view_projection, in NDC (post.taa); 0 when none
};

// The world position seen at pixel `texel` with stored depth `depth` (> 0).
vec3 world_position(Camera camera, ivec2 texel, float depth) {
  vec2 ndc = (vec2(texel) + 0.5) * camera.viewport.zw * 2.0 - 1.0;
  vec4 p = camera.inverse_view_projection * vec4(ndc, depth, 1.0);
  return p.xyz / p.w;
}

#endif
