// Shared helpers for plan tests: compile example files and synthetic graphs, shuffle a
// graph's nodes and links, and the sweep of random DAG settings the checkers run over.
#pragma once

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/scene_summary.h"
#include "nodes/builtin_schemas.h"
#include "tests/support/synthetic_graphs.h"

namespace lg::test {

inline std::vector<std::string> example_files() {
  return {"examples/minimal.json", "examples/default.json", "examples/post.json"};
}

inline std::vector<std::string> scene_files() {
  return {"", "examples/scenes/default.json", "examples/scenes/sun-only.json", "examples/scenes/thin-lens.json"};
}

inline Graph load_example(const std::string& path) {
  Diagnostics d;
  auto graph = load_graph_file(path, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return *graph;
}

inline SceneSummary load_scene(const std::string& path) {
  if (path.empty()) return default_scene_summary();
  Diagnostics d;
  auto scene = load_scene_summary(path, d);
  if (!scene) throw std::runtime_error(d.to_string());
  return *scene;
}

inline Plan compile_or_throw(const Graph& graph, const Registry& registry, const CompileOptions& options = {}) {
  Diagnostics d;
  CompileResult result = compile(graph, registry, options, d);
  if (!result.plan) throw std::runtime_error(d.to_string());
  return std::move(*result.plan);
}

inline Graph shuffled(Graph graph, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::shuffle(graph.nodes.begin(), graph.nodes.end(), rng);
  std::shuffle(graph.links.begin(), graph.links.end(), rng);
  return graph;
}

// One random DAG configuration of the >= 1,000 the checkers go through.
struct DagCase {
  RandomDagOptions dag;
  CompileOptions options;
};

inline std::vector<DagCase> dag_cases(size_t count) {
  std::vector<DagCase> cases;
  std::mt19937_64 rng(1234);
  for (size_t k = 0; k < count; ++k) {
    DagCase c;
    c.dag.nodes = 5 + rng() % 296;
    c.dag.dead_fraction = (rng() % 50) / 100.0;
    c.dag.history_fraction = (rng() % 3) * 0.25;
    c.dag.window = 2 + rng() % 20;
    c.dag.seed = k + 1;
    c.options.frame = {static_cast<uint32_t>(16 + rng() % 2000), static_cast<uint32_t>(16 + rng() % 1200)};
    c.options.alias.enabled = rng() % 8 != 0;
    c.options.alias.image_alignment = uint64_t{1} << (8 + rng() % 9);
    c.options.alias.buffer_alignment = uint64_t{1} << (4 + rng() % 5);
    cases.push_back(c);
  }
  return cases;
}

}  // namespace lg::test
