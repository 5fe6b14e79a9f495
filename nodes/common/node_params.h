// Reading a plan node's parameters in a kernel. The compiler has validated them against the
// schema and filled in defaults, so a missing or mistyped param here is a build defect: it
// throws naming the node and the param.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include "graph/plan.h"

namespace lg {

double param_number(const PlanNode& node, std::string_view name);
bool param_bool(const PlanNode& node, std::string_view name);
const std::string& param_string(const PlanNode& node, std::string_view name);
glm::vec3 param_float3(const PlanNode& node, std::string_view name);

}  // namespace lg
