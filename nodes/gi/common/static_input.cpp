#include "nodes/gi/common/static_input.h"

namespace lg {

std::optional<uint64_t> static_producer_key(const Plan& plan, const PlanAccess& access) {
  const int first = plan.resources[access.resource].first;
  if (first >= 0 && plan.passes[first].is_static) return plan.passes[first].cache_key;
  return std::nullopt;
}

}  // namespace lg
