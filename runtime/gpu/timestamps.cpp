#include "runtime/gpu/timestamps.h"

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

TimestampQueries::TimestampQueries(Context& context, uint32_t max_scopes) : context_(context), capacity_(max_scopes) {
  auto info = vk_struct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2 * max_scopes;
  vk_check(vkCreateQueryPool(context.device(), &info, nullptr, &pool_), "vkCreateQueryPool");
}

TimestampQueries::~TimestampQueries() { vkDestroyQueryPool(context_.device(), pool_, nullptr); }

void TimestampQueries::reset(VkCommandBuffer cmd) {
  vkCmdResetQueryPool(cmd, pool_, 0, 2 * capacity_);
  names_.clear();
}

uint32_t TimestampQueries::begin(VkCommandBuffer cmd, std::string name) {
  if (names_.size() == capacity_)
    throw GpuError("timestamp scope '" + name + "' is one more than the " + std::to_string(capacity_) + " allowed");
  const auto scope = static_cast<uint32_t>(names_.size());
  names_.push_back(std::move(name));
  // ALL_COMMANDS: the pass's time does not include waiting for work recorded before it.
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope);
  return scope;
}

void TimestampQueries::end(VkCommandBuffer cmd, uint32_t scope) {
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope + 1);
}

std::vector<ScopeTime> TimestampQueries::results() const {
  std::vector<ScopeTime> out;
  if (names_.empty()) return out;
  std::vector<uint64_t> ticks(2 * names_.size());
  vk_check(vkGetQueryPoolResults(context_.device(), pool_, 0, static_cast<uint32_t>(ticks.size()),
                                 ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
           "vkGetQueryPoolResults", "for timestamps");
  const uint32_t bits = context_.timestamp_valid_bits();
  const uint64_t mask = bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << bits) - 1;
  for (size_t s = 0; s < names_.size(); ++s) {
    const uint64_t elapsed = (ticks[2 * s + 1] - ticks[2 * s]) & mask;  // survives one wrap of the counter
    out.push_back({names_[s], static_cast<double>(elapsed) * context_.timestamp_period_ns() * 1e-6});
  }
  return out;
}

}  // namespace lg
