// The plan's memory on the device: one allocation per memory block and every resource the
// schedule touches created at its placement, so the compiler's aliasing is real in device
// memory. Also where each resource's bytes and layout stand between frames.
#pragma once

#include <variant>
#include <vector>

#include "graph/plan.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/memory.h"

namespace lg {

class Context;

// An image, a buffer, or nothing for a resource no pass touches (it has no placement).
using PlacedResource = std::variant<std::monostate, Image, Buffer>;

struct PlanMemory {
  std::vector<DeviceMemory> blocks;       // per Plan::blocks
  std::vector<PlacedResource> resources;  // per Plan::resources
};

// Each block takes the memory types that every image placed in it accepts.
PlanMemory allocate_plan_memory(Context& context, const Plan& plan);

// The layout each image is in after a frame (and before the next): that of its last barrier,
// or for a previous-frame copy without barriers, its partner's. Layout::none for buffers and
// for resources no pass touches.
std::vector<Layout> layouts_after_frame(const Plan& plan);

// Whether a later resource of the frame takes over `resource`'s bytes, so that after the frame
// they hold something else.
bool bytes_taken_over(const Plan& plan, int resource);

}  // namespace lg
