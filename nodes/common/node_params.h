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

// The `resolution_scale` param (1, 0.5, 1/3, 0.25: 1 over a whole number, which the schema's
// values hold every graph to) as that whole number k: the node computes at 1/k of the
// G-buffer's resolution and upsamples in blocks of k x k pixels.
int resolution_divisor(const PlanNode& node);

}  // namespace lg
