// GPU time per pass from timestamp queries: a begin and an end timestamp around each scope,
// converted to milliseconds with the device's timestamp period.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lg {

class Context;

struct ScopeTime {
  std::string name;
  double milliseconds = 0;
};

class TimestampQueries {
 public:
  TimestampQueries(Context& context, uint32_t max_scopes);
  ~TimestampQueries();
  TimestampQueries(const TimestampQueries&) = delete;
  TimestampQueries& operator=(const TimestampQueries&) = delete;

  // Starts a new set of scopes; call while recording, before the first begin().
  void reset(VkCommandBuffer cmd);
  // Timestamps after all earlier work; returns the scope for end().
  uint32_t begin(VkCommandBuffer cmd, std::string name);
  void end(VkCommandBuffer cmd, uint32_t scope);
  // The scopes since reset(), in begin order; waits until the GPU has written them.
  std::vector<ScopeTime> results() const;

 private:
  Context& context_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  uint32_t capacity_;
  std::vector<std::string> names_;
};

}  // namespace lg
