// The depth-buffer height-field reference: the G-buffer's own depth, read back, taken as an
// infinitely thick height field (everything behind a depth sample is solid), and the same
// stratified cosine rays as the full-scene reference (ao_sampling.h) traced against it. What
// GTAO could know at best from one depth buffer: GTAO against this is the method's error, this
// against the full-scene reference is what screen space cannot see.
#pragma once

#include <cstdint>
#include <vector>

#include "nodes/occlusion/reference/ao_image.h"
#include "nodes/occlusion/reference/ao_sampling.h"
#include "runtime/scene/scene_view.h"

namespace lg {

struct GbufferReadback {
  uint32_t width = 0, height = 0;
  std::vector<float> depth;   // device depth, one per pixel (0: nothing there)
  std::vector<float> normal;  // RGBA per pixel as stored (nodes/common/gbuffer_normal.h), world space
};

// Pixels whose x and y are multiples of `stride` get a reference; the rest stay NaN (a 1280x720
// height field costs about a million pixel lookups per pixel). Off screen and behind the near
// plane a ray escapes: the buffer knows nothing there. Between pixel centres the device depth
// is interpolated bilinearly, which is exact on planes (device depth is affine on the screen
// for a plane), so an open plane gives exactly 1. Throws std::invalid_argument when the
// buffers do not hold width x height pixels.
AoImage trace_height_field_reference(const CameraView& camera, const GbufferReadback& gbuffer,
                                     const AoSettings& settings, uint32_t stride = 1);

}  // namespace lg
