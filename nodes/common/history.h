// Whether a temporal node may read its history input this frame: it is linked, this is not the
// plan's first frame (the executor starts history cleared, and a resize or recompile makes a new
// plan) and the camera did not cut (FrameTiming::camera_cut: the history shows another view).
// post.exposure, post.taa, occlusion.gtao and lighting.ssr restart from this frame otherwise.
#pragma once

#include <string_view>

#include "runtime/exec/node_kernel.h"
#include "runtime/scene/scene_view.h"

namespace lg {

inline bool history_usable(const PassContext& ctx, std::string_view slot) {
  return ctx.has(slot) && ctx.frame_index() > 0 && !ctx.scene().camera_cut;
}

}  // namespace lg
