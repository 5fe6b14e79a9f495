// Executor::adopt_cached_results: static results carried from one executor to the next, so a
// recompiled plan does not recompute environment convolutions and lookup tables; and their
// bytes read and loaded for keeping them on disk between runs.
#include <algorithm>
#include <optional>

#include "runtime/exec/executor.h"
#include "runtime/exec/static_results_file.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image_copy.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/gpu/transfer.h"

namespace lg {
namespace {

std::optional<int> find_resource(const Plan& plan, const std::string& name) {
  for (size_t r = 0; r < plan.resources.size(); ++r)
    if (plan.resources[r].desc.name == name) return static_cast<int>(r);
  return std::nullopt;
}

bool same_shape(const LoweredResource& a, const LoweredResource& b) {
  return a.kind == b.kind && a.format == b.format && a.width == b.width && a.height == b.height &&
         a.layers == b.layers && a.mips == b.mips && a.bytes == b.bytes;
}

}  // namespace

bool Executor::adopt_cached_results(Executor& previous) {
  if (previous.frames_ == 0) return false;
  bool any = false;
  for (const PlanPass& pass : plan_.passes) {
    if (!pass.is_static) continue;
    const auto& theirs = previous.plan_.passes;
    auto match = std::find_if(theirs.begin(), theirs.end(), [&](const PlanPass& q) {
      return q.is_static && q.name == pass.name && previous.ran_keys_[&q - theirs.data()] == pass.cache_key;
    });
    if (match == theirs.end()) return false;
    any = true;
  }
  if (!any) return false;
  std::vector<std::pair<int, int>> copies;  // (ours, theirs)
  for (int r : stored_resources()) {
    const PlanResource& ours = plan_.resources[r];
    std::optional<int> theirs = find_resource(previous.plan_, ours.desc.name);
    if (!theirs || !same_shape(ours.desc, previous.plan_.resources[*theirs].desc)) return false;
    copies.emplace_back(r, *theirs);
  }
  submitter_.run([&](VkCommandBuffer cmd) {
    for (auto [r, t] : copies) {
      PlacedResource& to = memory_.resources[r];
      const PlacedResource& from = previous.memory_.resources[t];
      if (auto* image = std::get_if<Image>(&to)) {
        copy_image(cmd, std::get<Image>(from), vk_layout(previous.layouts_[t]), *image, vk_layout(layouts_[r]));
      } else if (auto* buffer = std::get_if<Buffer>(&to)) {
        const VkBufferCopy region{0, 0, buffer->size()};
        memory_barrier(cmd);
        vkCmdCopyBuffer(cmd, std::get<Buffer>(from).handle(), buffer->handle(), 1, &region);
        memory_barrier(cmd);
      }
    }
  });
  for (size_t p = 0; p < plan_.passes.size(); ++p)
    if (plan_.passes[p].is_static) ran_keys_[p] = plan_.passes[p].cache_key;
  return true;
}

std::vector<int> Executor::stored_resources() const {
  std::vector<int> out;
  for (size_t r = 0; r < plan_.resources.size(); ++r)
    if (is_static_result(plan_.resources[r])) out.push_back(int(r));
  return out;
}

std::vector<StoredResult> Executor::read_cached_results() {
  if (frames_ == 0 || !caches_valid()) return {};
  std::vector<StoredResult> out;
  for (int r : stored_resources()) {
    StoredResult& result = out.emplace_back();
    result.name = plan_.resources[r].desc.name;
    const PlacedResource& placed = memory_.resources[r];
    if (auto* image = std::get_if<Image>(&placed))
      result.bytes = read_image_bytes(submitter_, *image, vk_layout(layouts_[r]));
    else
      result.bytes = lg::read_buffer(submitter_, std::get<Buffer>(placed));
  }
  return out;
}

std::string Executor::load_cached_results(std::span<const StoredResult> results) {
  if (frames_ > 0) return "the executor has run frames already";
  const std::vector<int> stored = stored_resources();
  if (results.size() != stored.size())
    return "it holds " + std::to_string(results.size()) + " results, the plan keeps " + std::to_string(stored.size());
  for (size_t i = 0; i < stored.size(); ++i) {
    const std::string& name = plan_.resources[stored[i]].desc.name;
    const PlacedResource& placed = memory_.resources[stored[i]];
    const auto* image = std::get_if<Image>(&placed);
    const uint64_t size = image ? image_byte_size(*image) : std::get<Buffer>(placed).size();
    if (results[i].name != name) return "it holds '" + results[i].name + "' where the plan keeps '" + name + "'";
    if (results[i].bytes.size() != size)
      return "it holds " + std::to_string(results[i].bytes.size()) + " bytes of '" + name + "', the plan keeps " +
             std::to_string(size);
  }
  for (size_t i = 0; i < stored.size(); ++i) {
    const int r = stored[i];
    if (auto* image = std::get_if<Image>(&memory_.resources[r]))
      upload_image_bytes(submitter_, *image, results[i].bytes, vk_layout(layouts_[r]));
    else
      upload_buffer(submitter_, std::get<Buffer>(memory_.resources[r]), results[i].bytes);
  }
  for (size_t p = 0; p < plan_.passes.size(); ++p)
    if (plan_.passes[p].is_static) ran_keys_[p] = plan_.passes[p].cache_key;
  return {};
}

}  // namespace lg
