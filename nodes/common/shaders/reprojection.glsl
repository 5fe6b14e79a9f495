// Temporal reprojection, shared by the nodes that keep history (post.taa, occlusion.gtao's
// accumulation, lighting.ssr's trace and resolve): where the surface seen at `uv` this frame
// was in last frame's image, following the G-buffer's motion vector (uv now - uv then, without
// the camera's jitter: runtime/scene/camera_jitter.h). False when that lies outside the image
// (or the motion is not finite), where the history has nothing for it.
#ifndef LG_REPROJECTION_GLSL
#define LG_REPROJECTION_GLSL

bool reproject(vec2 uv, vec2 motion, out vec2 previous_uv) {
  previous_uv = uv - motion;
  return all(greaterThanEqual(previous_uv, vec2(0.0))) && all(lessThanEqual(previous_uv, vec2(1.0)));
}

#endif
