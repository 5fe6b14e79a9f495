// Entity handles of the ECS world: an index into the world's slots plus the generation the slot
// had when the entity was made, so that a handle kept past destroy() is detected as stale.
#pragma once

#include <cstdint>
#include <limits>

namespace lg {

struct Entity {
  static constexpr uint32_t no_index = std::numeric_limits<uint32_t>::max();
  uint32_t index = no_index;
  uint32_t generation = 0;

  bool is_null() const { return index == no_index; }
  // One number per entity, unique over the world's lifetime (for matching across frames).
  uint64_t id() const { return (static_cast<uint64_t>(generation) << 32) | index; }
  friend bool operator==(Entity, Entity) = default;
};

}  // namespace lg
