// The example graphs the runtime tests run, and compiling one with the built-in schemas for a
// device, placed with the device's own sizes and alignments as an executor needs.
#pragma once

#include <stdexcept>
#include <string>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"
#include "runtime/gpu/plan_resources.h"

namespace lg::test {

inline const std::string example_graphs[] = {"examples/minimal.json", "examples/default.json", "examples/post.json"};

// "examples/default.json" -> "default", for test names.
inline std::string example_name(const std::string& path) {
  return path.substr(9, path.size() - 14);
}

// Throws with the diagnostics on errors.
inline Plan compile_example(const Context& context, const std::string& path, FrameSize frame) {
  Diagnostics d;
  std::optional<Graph> graph = load_graph_file(path, d);
  if (!graph) throw std::runtime_error(d.to_string());
  CompileOptions options;
  options.frame = frame;
  options.alias = device_alias_options(context);
  CompileResult result = compile(*graph, builtin_registry(), options, d);
  if (!result.plan) throw std::runtime_error(d.to_string());
  return std::move(*result.plan);
}

}  // namespace lg::test
