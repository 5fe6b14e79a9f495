// Whether what a GI node reads is the same every frame (gi.lpv, gi.voxel keep work built from
// the sky's SH while it does not change).
#pragma once

#include <cstdint>
#include <optional>

#include "graph/plan.h"

namespace lg {

// The cache key of the static pass that made what `access` reads (its resource's first pass,
// its producer: that pass's node type, params and static inputs), or none where it is not a
// static result of the plan (an animated sky), which may change in any frame.
std::optional<uint64_t> static_producer_key(const Plan& plan, const PlanAccess& access);

}  // namespace lg
