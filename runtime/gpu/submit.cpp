#include "runtime/gpu/submit.h"

#include <string>

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

Submitter::Submitter(Context& context) : context_(context) {
  auto pool = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = context.queue_family();
  vk_check(vkCreateCommandPool(context.device(), &pool, nullptr, &pool_), "vkCreateCommandPool");
  auto alloc = vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  auto fence = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  VkResult r = vkAllocateCommandBuffers(context.device(), &alloc, &cmd_);
  if (r == VK_SUCCESS) r = vkCreateFence(context.device(), &fence, nullptr, &fence_);
  if (r != VK_SUCCESS) vkDestroyCommandPool(context.device(), pool_, nullptr);
  vk_check(r, "vkAllocateCommandBuffers or vkCreateFence");
}

Submitter::~Submitter() {
  // Work still running after a timeout keeps the command buffer: leave it rather than free it
  // under the device's feet.
  if (pending_ && vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, 0) != VK_SUCCESS) return;
  vkDestroyFence(context_.device(), fence_, nullptr);
  vkDestroyCommandPool(context_.device(), pool_, nullptr);
}

void Submitter::wait(std::chrono::milliseconds timeout, const char* what) {
  const uint64_t ns = static_cast<uint64_t>(std::chrono::nanoseconds(timeout).count());
  VkResult r = vkWaitForFences(context_.device(), 1, &fence_, VK_TRUE, ns);
  if (r == VK_TIMEOUT)
    throw GpuError(std::string("vkWaitForFences timed out after ") + std::to_string(timeout.count()) + " ms " + what,
                   VK_TIMEOUT);
  vk_check(r, "vkWaitForFences", what);
  pending_ = false;
}

void Submitter::run(const std::function<void(VkCommandBuffer)>& record, std::chrono::milliseconds timeout) {
  if (pending_) wait(timeout, "waiting for the previous submission");
  vk_check(vkResetFences(context_.device(), 1, &fence_), "vkResetFences");
  vk_check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
  auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vk_check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
  try {
    record(cmd_);
  } catch (...) {
    vkEndCommandBuffer(cmd_);
    throw;
  }
  vk_check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");

  auto buffer = vk_struct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  buffer.commandBuffer = cmd_;
  auto submit = vk_struct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &buffer;
  vk_check(vkQueueSubmit2(context_.queue(), 1, &submit, fence_), "vkQueueSubmit2");
  pending_ = true;
  wait(timeout, "waiting for a one-shot submission");
}

}  // namespace lg
