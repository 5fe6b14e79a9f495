#include "runtime/gpu/host_buffer.h"

#include <algorithm>
#include <cstring>

namespace lg {

HostBuffer::HostBuffer(Context& context, std::string name, VkBufferUsageFlags usage)
    : context_(context), name_(std::move(name)), usage_(usage) {}

void HostBuffer::write(std::span<const std::byte> bytes) {
  const uint64_t needed = std::max<uint64_t>(bytes.size(), 16);
  if (!buffer_.handle() || buffer_.size() < needed) {
    // Doubling keeps a list that grows frame by frame from reallocating every frame.
    const uint64_t size = std::max(needed, 2 * (buffer_.handle() ? buffer_.size() : 0));
    buffer_ = Buffer::dedicated(context_, {.name = name_, .size = size, .usage = usage_}, MemoryUse::upload);
  }
  if (!bytes.empty()) std::memcpy(buffer_.mapped(), bytes.data(), bytes.size());
}

}  // namespace lg
