// A host-visible buffer that the CPU rewrites every frame (a pass's constants, per-draw data,
// light lists), grown when a write needs more room. The executor waits for each frame before
// the next is recorded, so rewriting or regrowing it between frames is safe.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "runtime/gpu/buffer.h"

namespace lg {

class HostBuffer {
 public:
  HostBuffer(Context& context, std::string name, VkBufferUsageFlags usage);

  // Replaces the contents with `bytes` (at least 16 bytes are kept, so an empty list still
  // binds). The previous handle is invalid afterwards when the buffer had to grow.
  void write(std::span<const std::byte> bytes);
  template <typename T>
  void write(const std::vector<T>& items) {
    write(std::as_bytes(std::span(items)));
  }
  template <typename T>
  void write_value(const T& value) {
    write(std::as_bytes(std::span(&value, 1)));
  }

  VkBuffer handle() const { return buffer_.handle(); }

 private:
  Context& context_;
  std::string name_;
  VkBufferUsageFlags usage_;
  Buffer buffer_;
};

}  // namespace lg
