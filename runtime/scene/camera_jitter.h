// Sub-pixel jitter of the camera's projection for temporal anti-aliasing (post.taa): each frame
// the whole image moves by a fraction of a pixel, taken from the Halton (2, 3) sequence, so that
// frames accumulated over time sample the pixel's area instead of its centre. Every pass that
// rasterizes or reconstructs positions uses jittered_projection(); motion vectors leave the
// jitter out (nodes/scene/gbuffer), so reprojection sees only the scene's motion.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

// Frames before the jitter repeats: 16 points of Halton (2, 3) cover the pixel evenly enough
// for an exponential history of about 10 frames (post.taa's default feedback, 0.9).
inline constexpr uint32_t kJitterSequenceLength = 16;

// The radical inverse of `index` in `base`: element `index` of the Halton sequence in [0, 1).
double halton(uint32_t index, uint32_t base);

// Sample `index` of the Halton (2, 3) sequence (from its second element, as the first is 0),
// as an offset in pixels from the pixel's centre, in [-0.5, 0.5) each way.
glm::vec2 halton_jitter_pixels(uint32_t index);

// The jitter of frame `frame`: the sequence of kJitterSequenceLength samples, repeated.
glm::vec2 frame_jitter_pixels(uint64_t frame);

// An offset in pixels of a width x height grid as one in normalized device coordinates (2 / size
// per pixel; +y is down in Vulkan's clip space, as it is in the image).
glm::vec2 jitter_ndc(glm::vec2 pixels, uint32_t width, uint32_t height);

// The camera's projection moved by its jitter: clip.xy += jitter * clip.w. Without a jitter,
// the projection itself, bit for bit.
glm::mat4 jittered_projection(const CameraView& camera);

}  // namespace lg
