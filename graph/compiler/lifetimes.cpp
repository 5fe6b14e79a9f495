#include "graph/compiler/lifetimes.h"

#include <algorithm>

namespace lg {

CachedVector<Lifetime> lifetimes(const LoweredGraph& lowered, const CachedVector<int>& order) {
  CachedVector<Lifetime> out(lowered.resources.size());
  for (int pos = 0; pos < static_cast<int>(order.size()); ++pos) {
    for (const auto& a : lowered.passes[order[pos]].accesses) {
      Lifetime& l = out[a.resource];
      if (l.first < 0) l.first = pos;
      l.last = std::max(l.last, pos);
    }
  }
  const int end = static_cast<int>(order.size()) - 1;
  for (size_t r = 0; r < out.size(); ++r) {
    if (!out[r].used()) continue;
    if (lowered.resources[r].lifetime != ResourceLifetime::transient) out[r].last = end;
    if (lowered.resources[r].lifetime == ResourceLifetime::cached || lowered.resources[r].lifetime == ResourceLifetime::history)
      out[r].first = 0;
  }
  return out;
}

JsonValue dump_lifetimes(const LoweredGraph& lowered, const CachedVector<Lifetime>& lives) {
  JsonValue out = JsonValue::object();
  for (size_t r = 0; r < lives.size(); ++r) {
    JsonValue range = JsonValue::array();
    range.push(lives[r].first);
    range.push(lives[r].last);
    out.set(lowered.resources[r].name, range);
  }
  return out;
}

}  // namespace lg
