// Prints a Plan: JSON (everything, for tools), Graphviz dot (passes and resources as a graph)
// and a text table (for people: pass order, skipped nodes with reasons, memory).
#pragma once

#include <string>

#include "graph/json_value.h"
#include "graph/plan.h"

namespace lg {

JsonValue plan_to_json(const Plan& plan);
std::string plan_to_dot(const Plan& plan);
std::string plan_to_text(const Plan& plan);

// "12.3 MiB"
std::string format_bytes(uint64_t bytes);

}  // namespace lg
