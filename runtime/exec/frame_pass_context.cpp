#include "runtime/exec/frame_pass_context.h"

#include "runtime/exec/executor_error.h"
#include "runtime/gpu/sampler.h"

namespace lg {

const PlanAccess* FramePassContext::find(std::string_view slot, int component) const {
  for (const PlanAccess& a : frame_.plan.accesses_of(pass_))
    if (frame_.plan.slot_of(a) == slot && a.component == component) return &a;
  return nullptr;
}

bool FramePassContext::has(std::string_view slot, int component) const {
  return find(slot, component) != nullptr;
}

void FramePassContext::missing(std::string_view slot, int component, std::string_view what) const {
  std::string bound;
  for (const PlanAccess& a : frame_.plan.accesses_of(pass_))
    bound +=
        (bound.empty() ? "" : ", ") + frame_.plan.slot_of(a) + (a.component ? "." + std::to_string(a.component) : "");
  // The executor prefixes the pass's name.
  throw ExecutorError("node '" + node().id + "' (" + node().type + ") has no " + std::string(what) + " at '" +
                      std::string(slot) + (component ? "' component " + std::to_string(component) : "'") +
                      " in this pass; it binds " + (bound.empty() ? "nothing" : bound));
}

Image& FramePassContext::image(std::string_view slot, int component) {
  if (const PlanAccess* a = find(slot, component))
    if (auto* image = std::get_if<Image>(&frame_.resources[a->resource])) return *image;
  missing(slot, component, "image");
}

Buffer& FramePassContext::buffer(std::string_view slot) {
  if (const PlanAccess* a = find(slot, 0))
    if (auto* buffer = std::get_if<Buffer>(&frame_.resources[a->resource])) return *buffer;
  missing(slot, 0, "buffer");
}

NodeKernel* FramePassContext::producer(std::string_view slot) {
  if (!slot.starts_with("in.")) return nullptr;
  const PlanAccess* a = find(slot, 0);
  if (!a) return nullptr;
  const int node = frame_.plan.resources[a->resource].desc.node;
  return node >= 0 && size_t(node) < frame_.kernels.size() ? frame_.kernels[node].get() : nullptr;
}

VkSampler FramePassContext::linear_sampler() {
  return frame_.linear.handle();
}
VkSampler FramePassContext::nearest_sampler() {
  return frame_.nearest.handle();
}

}  // namespace lg
