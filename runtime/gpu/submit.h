// One-shot command submission: record into a command buffer, submit it to the context's queue
// and wait on a fence. A wait longer than the timeout throws GpuError instead of hanging.
#pragma once

#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>

namespace lg {

class Context;

inline constexpr std::chrono::milliseconds default_submit_timeout{60'000};

class Submitter {
 public:
  explicit Submitter(Context& context);
  ~Submitter();
  Submitter(const Submitter&) = delete;
  Submitter& operator=(const Submitter&) = delete;

  Context& context() const { return context_; }

  // Records with `record`, submits and waits. After a timeout the work may still be running:
  // the next run() first waits for it (with its own timeout) before reusing the command buffer.
  void run(const std::function<void(VkCommandBuffer)>& record,
           std::chrono::milliseconds timeout = default_submit_timeout);

 private:
  void wait(std::chrono::milliseconds timeout, const char* what);

  Context& context_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;  // submitted and not yet seen finished
};

}  // namespace lg
