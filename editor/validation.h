// Live validation: compiles the graph exactly as the runtime would load it (written out and
// parsed back, so structural mistakes show too) against the built-in schemas and the scene the
// preview renders (the default one without a preview), and ties every diagnostic to the node
// it is about.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/graph.h"
#include "graph/plan.h"
#include "graph/scene_summary.h"

namespace lg::editor {

struct Problem {
  Diagnostic diagnostic;
  std::string node;  // id of the node it is about; empty for the graph as a whole
};

struct Validation {
  std::optional<Plan> plan;  // nullopt when there are errors
  std::vector<Problem> problems;
  bool has_errors() const;
};

Validation validate_graph(const Graph& graph, const SceneSummary& scene = default_scene_summary());

// The node a JSON pointer is about: /nodes/N/..., a link's target (/links/N/to) or source
// (/links/N/from), or a requested output (/outputs/N); empty when none.
std::string node_of_pointer(const Graph& graph, const std::string& pointer);
// The param a pointer is about (/nodes/N/params/NAME...), or empty.
std::string param_of_pointer(const std::string& pointer);

}  // namespace lg::editor
