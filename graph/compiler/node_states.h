// IR of phases 4 and 5 (specialize, cull): what happens to each node and pass, and why.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "graph/block_cache.h"

namespace lg {

struct NodeState {
  enum class Kind : uint8_t { active, bypassed, culled } kind = Kind::active;
  std::string reason;                      // for bypassed and culled nodes
  int bypass_rule = -1;                    // index into NodeSchema::bypass when bypassed
  std::vector<std::string> dropped_passes; // per schema pass: why it is dropped; empty if none is

  std::string_view why_dropped(size_t pass) const {
    return pass < dropped_passes.size() ? std::string_view(dropped_passes[pass]) : std::string_view();
  }
};

using NodeStates = CachedVector<NodeState>;

// "active", "bypassed", "culled": as plans, dumps and frame statistics write them.
inline std::string_view node_state_name(NodeState::Kind k) {
  constexpr std::string_view names[] = {"active", "bypassed", "culled"};
  return names[static_cast<int>(k)];
}

}  // namespace lg
