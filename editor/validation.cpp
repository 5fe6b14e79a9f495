#include "editor/validation.h"

#include <algorithm>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg::editor {

bool Validation::has_errors() const {
  return std::any_of(problems.begin(), problems.end(),
                     [](const Problem& p) { return p.diagnostic.severity == Severity::error; });
}

// "/links/3/to" -> ("links", 3, "/to")
static bool split_pointer(const std::string& pointer, std::string& list, size_t& index, std::string& rest) {
  if (pointer.size() < 2 || pointer[0] != '/') return false;
  const size_t slash = pointer.find('/', 1);
  if (slash == std::string::npos) return false;
  list = pointer.substr(1, slash - 1);
  const size_t end = pointer.find('/', slash + 1);
  const std::string number = pointer.substr(slash + 1, end == std::string::npos ? std::string::npos : end - slash - 1);
  if (number.empty() || !std::all_of(number.begin(), number.end(), ::isdigit)) return false;
  index = std::stoul(number);
  rest = end == std::string::npos ? "" : pointer.substr(end);
  return true;
}

std::string node_of_pointer(const Graph& graph, const std::string& pointer) {
  std::string list, rest;
  size_t i = 0;
  if (!split_pointer(pointer, list, i, rest)) return {};
  if (list == "nodes" && i < graph.nodes.size()) return graph.nodes[i].id;
  if (list == "links" && i < graph.links.size())
    return rest.starts_with("/from") ? graph.links[i].from.node : graph.links[i].to.node;
  if (list == "outputs" && i < graph.outputs.size()) return graph.outputs[i].port.node;
  return {};
}

std::string param_of_pointer(const std::string& pointer) {
  std::string list, rest;
  size_t i = 0;
  if (!split_pointer(pointer, list, i, rest) || list != "nodes" || !rest.starts_with("/params/")) return {};
  const std::string name = rest.substr(8);
  return name.substr(0, name.find('/'));
}

Validation validate_graph(const Graph& graph, const SceneSummary& scene) {
  Validation result;
  Diagnostics diagnostics(graph.file);
  std::optional<Graph> reread = parse_graph(graph_to_json(graph), diagnostics);
  if (reread) {
    reread->file = graph.file;
    CompileOptions options;
    options.scene = scene;
    CompileResult compiled = compile(*reread, builtin_registry(), options, diagnostics);
    result.plan = std::move(compiled.plan);
  }
  for (const Diagnostic& d : diagnostics.items()) result.problems.push_back({d, node_of_pointer(graph, d.pointer)});
  return result;
}

}  // namespace lg::editor
