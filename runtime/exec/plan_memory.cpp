#include "runtime/exec/plan_memory.h"

#include <algorithm>
#include <string>

#include "runtime/gpu/context.h"
#include "runtime/gpu/plan_resources.h"

namespace lg {

PlanMemory allocate_plan_memory(Context& context, const Plan& plan) {
  std::vector<uint32_t> type_bits(plan.blocks.size(), ~0u);
  for (const PlanResource& r : plan.resources)
    if (r.placement.block >= 0 && r.desc.kind != ResourceKind::buffer)
      type_bits[r.placement.block] &= Image::requirements(context, image_desc(r.desc)).memoryTypeBits;
  PlanMemory out;
  for (size_t b = 0; b < plan.blocks.size(); ++b)
    out.blocks.emplace_back(context, plan.blocks[b].size, type_bits[b], MemoryUse::device_local,
                            "block " + std::to_string(b));
  out.resources.reserve(plan.resources.size());
  for (const PlanResource& r : plan.resources) {
    PlacedResource& slot = out.resources.emplace_back();
    if (r.placement.block < 0) continue;
    const DeviceMemory& block = out.blocks[r.placement.block];
    if (r.desc.kind == ResourceKind::buffer)
      slot = Buffer::placed(context, buffer_desc(r.desc), block, r.placement.offset, r.placement.size);
    else
      slot = Image::placed(context, image_desc(r.desc), block, r.placement.offset, r.placement.size);
  }
  return out;
}

std::vector<Layout> layouts_after_frame(const Plan& plan) {
  std::vector<Layout> out(plan.resources.size(), Layout::none);
  for (const Barrier& b : plan.barriers) out[b.resource] = b.new_layout;  // sorted by pass
  for (size_t r = 0; r < plan.resources.size(); ++r) {
    const PlanResource& res = plan.resources[r];
    if (res.desc.history_of >= 0 && res.first >= 0 && out[r] == Layout::none) out[r] = out[res.desc.history_of];
  }
  return out;
}

bool bytes_taken_over(const Plan& plan, int resource) {
  return std::find(plan.predecessors.begin(), plan.predecessors.end(), resource) != plan.predecessors.end();
}

}  // namespace lg
