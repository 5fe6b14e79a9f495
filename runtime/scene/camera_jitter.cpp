#include "runtime/scene/camera_jitter.h"

namespace lg {

double halton(uint32_t index, uint32_t base) {
  double result = 0.0, fraction = 1.0;
  for (; index > 0; index /= base) {
    fraction /= base;
    result += fraction * double(index % base);
  }
  return result;
}

glm::vec2 halton_jitter_pixels(uint32_t index) {
  return {float(halton(index + 1, 2) - 0.5), float(halton(index + 1, 3) - 0.5)};
}

glm::vec2 frame_jitter_pixels(uint64_t frame) {
  return halton_jitter_pixels(uint32_t(frame % kJitterSequenceLength));
}

glm::vec2 jitter_ndc(glm::vec2 pixels, uint32_t width, uint32_t height) {
  return {2.0f * pixels.x / float(width), 2.0f * pixels.y / float(height)};
}

glm::mat4 jittered_projection(const CameraView& camera) {
  glm::mat4 p = camera.projection;
  if (!camera.jitter) return p;
  // Adding jitter * w to clip x and y: the w row (row 3) scaled into rows 0 and 1.
  for (int column = 0; column < 4; ++column) {
    p[column][0] += camera.jitter->x * p[column][3];
    p[column][1] += camera.jitter->y * p[column][3];
  }
  return p;
}

}  // namespace lg
