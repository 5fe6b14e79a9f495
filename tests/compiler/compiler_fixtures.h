// Helpers shared by the compiler tests: load the examples and scene summaries, build small
// graphs in code, compile with the real or the synthetic registry, look passes, resources and
// nodes up by name, shuffle a graph's nodes and links, and the sweep of random-DAG settings
// the property tests run over.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "graph/compiler.h"
#include "graph/compiler/cull.h"
#include "graph/compiler/lower.h"
#include "graph/compiler/resolve.h"
#include "graph/compiler/specialize.h"
#include "graph/compiler/validate.h"
#include "graph/graph_io.h"
#include "graph/scene_summary.h"
#include "nodes/builtin_schemas.h"
#include "tests/support/synthetic_graphs.h"

namespace lg::test {

// The *.json files of a folder, sorted, as paths relative to the source root (tests run there).
inline std::vector<std::string> json_files_in(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      out.push_back(folder + "/" + entry.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Every example graph: a new one is picked up without touching the tests.
inline const std::vector<std::string>& example_paths() {
  static const std::vector<std::string> paths = json_files_in("examples");
  return paths;
}

// "" stands for the embedded default scene, then every example scene summary.
inline const std::vector<std::string>& scene_paths() {
  static const std::vector<std::string> paths = [] {
    std::vector<std::string> p = {""};
    for (auto& f : json_files_in("examples/scenes")) p.push_back(f);
    return p;
  }();
  return paths;
}

inline Graph load_example(const std::string& path) {
  Diagnostics d;
  auto g = load_graph_file(path, d);
  if (!g) throw std::runtime_error("cannot load " + path + ":\n" + d.to_string());
  return std::move(*g);
}

inline SceneSummary load_scene(const std::string& path) {
  if (path.empty()) return default_scene_summary();
  Diagnostics d;
  auto s = load_scene_summary(path, d);
  if (!s) throw std::runtime_error("cannot load " + path + ":\n" + d.to_string());
  return *s;
}

inline Graph parse_text(std::string_view text) {
  Diagnostics d("inline graph");
  auto g = parse_graph_text(text, d);
  if (!g) throw std::runtime_error(d.to_string());
  return std::move(*g);
}

// Compiles or throws with the diagnostics (GoogleTest reports the exception as a failure).
inline Plan compile_ok(const Graph& graph, const Registry& registry, const CompileOptions& options = {}) {
  Diagnostics d(graph.file);
  CompileResult result = compile(graph, registry, options, d);
  if (!result.plan) throw std::runtime_error("compile failed:\n" + d.to_string());
  return std::move(*result.plan);
}

inline Plan compile_example(const std::string& path, const std::string& scene = "", FrameSize frame = {}) {
  CompileOptions options;
  options.scene = load_scene(scene);
  options.frame = frame;
  return compile_ok(load_example(path), builtin_registry(), options);
}

// Compiles a graph that must fail; returns every diagnostic as text.
inline std::string compile_errors(const Graph& graph, const Registry& registry, const CompileOptions& options = {}) {
  Diagnostics d(graph.file);
  CompileResult result = compile(graph, registry, options, d);
  if (result.plan) return {};
  return d.to_string();
}

// The phases up to lower, run one by one; the graph is owned here because the IRs point into it.
struct Lowered {
  Graph graph;
  ResolvedGraph resolved;
  CachedVector<int> node_order;
  NodeStates states;
  LoweredGraph lowered;
};

inline std::unique_ptr<Lowered> lower_graph(Graph g, const Registry& registry, const CompileOptions& options = {}) {
  auto out = std::make_unique<Lowered>();
  out->graph = std::move(g);
  Diagnostics d;
  out->resolved = resolve(out->graph, registry, d);
  auto order = validate(out->resolved, options.roots, d);
  if (!order || d.has_errors()) throw std::runtime_error(d.to_string());
  out->node_order = *order;
  out->states = cull(out->resolved, specialize(out->resolved, options.scene));
  auto lowered = lower(out->resolved, out->node_order, out->states, options.frame, options.roots, d);
  if (!lowered) throw std::runtime_error(d.to_string());
  out->lowered = std::move(*lowered);
  return out;
}

// ---- building graphs in code ----

inline GraphNode& add_node(Graph& g, std::string id, std::string type, JsonValue params = JsonValue::object()) {
  GraphNode n;
  n.id = std::move(id);
  n.type = std::move(type);
  n.params = std::move(params);
  g.nodes.push_back(std::move(n));
  return g.nodes.back();
}

inline PortRef port_ref(const std::string& text) {
  size_t dot = text.find('.');
  return {text.substr(0, dot), text.substr(dot + 1)};
}

inline void add_link(Graph& g, const std::string& from, const std::string& to) {
  g.links.push_back({port_ref(from), port_ref(to), {}, {}});
}

inline bool remove_link_to(Graph& g, const std::string& to) {
  auto before = g.links.size();
  std::erase_if(g.links, [&](const GraphLink& l) { return l.to.text() == to; });
  return g.links.size() != before;
}

inline GraphNode& node_named(Graph& g, std::string_view id) {
  for (auto& n : g.nodes)
    if (n.id == id) return n;
  throw std::runtime_error("no node " + std::string(id));
}

inline Graph shuffled(Graph g, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::shuffle(g.nodes.begin(), g.nodes.end(), rng);
  std::shuffle(g.links.begin(), g.links.end(), rng);
  return g;
}

// ---- looking things up in a plan ----

inline int pass_at(const Plan& plan, std::string_view name) {
  for (size_t p = 0; p < plan.passes.size(); ++p)
    if (plan.passes[p].name == name) return static_cast<int>(p);
  return -1;
}

inline int resource_at(const Plan& plan, std::string_view name) {
  for (size_t r = 0; r < plan.resources.size(); ++r)
    if (plan.resources[r].desc.name == name) return static_cast<int>(r);
  return -1;
}

inline const PlanNode* plan_node(const Plan& plan, std::string_view id) {
  for (const auto& n : plan.nodes)
    if (n.id == id) return &n;
  return nullptr;
}

// The resource a pass binds to a slot ("in.color"), or -1.
inline int resource_in_slot(const Plan& plan, std::string_view pass, std::string_view slot) {
  int p = pass_at(plan, pass);
  if (p < 0) return -1;
  for (const auto& a : plan.accesses_of(plan.passes[p]))
    if (plan.slot_of(a) == slot) return a.resource;
  return -1;
}

inline std::string resource_name(const Plan& plan, int r) {
  return r >= 0 ? plan.resources[r].desc.name : std::string("(none)");
}

inline bool is_persistent(ResourceLifetime l) {
  return l == ResourceLifetime::cached || l == ResourceLifetime::history;
}

// The random DAGs only loop a temporal node back onto itself; real graphs also read last frame's
// result of another node (TAA reads the tonemapped frame, say). Points every history link at
// the image output of a node picked at random, earlier or later in the frame.
inline Graph with_history_from_elsewhere(Graph g, uint64_t seed) {
  std::vector<std::string> images;
  for (const auto& n : g.nodes)
    for (const char* type : {"test.source", "test.filter", "test.blend", "test.temporal", "test.shade", "test.apply"})
      if (n.type == type) images.push_back(n.id);
  std::mt19937_64 rng(seed);
  for (auto& l : g.links)
    if (l.to.port == "history" && !images.empty())
      l.from = {images[std::uniform_int_distribution<size_t>(0, images.size() - 1)(rng)], "out"};
  return g;
}

// ---- the random-DAG sweep ----

struct DagCase {
  RandomDagOptions dag;
  CompileOptions options;
  std::string describe() const {
    return "nodes=" + std::to_string(dag.nodes) + " dead=" + std::to_string(dag.dead_fraction) +
           " history=" + std::to_string(dag.history_fraction) + " window=" + std::to_string(dag.window) +
           " seed=" + std::to_string(dag.seed) + " frame=" + std::to_string(options.frame.width) + "x" +
           std::to_string(options.frame.height) + " alias=" + (options.alias.enabled ? "on" : "off") +
           " align=" + std::to_string(options.alias.image_alignment) + "/" +
           std::to_string(options.alias.buffer_alignment);
  }
};

// `count` settings, deterministic for `salt`: sizes from 5 to 300 nodes (small ones often, the
// largest always included), dead and history shares from none to most, frame sizes from tiny
// to 4K, power-of-two and odd alignments, aliasing mostly on.
inline std::vector<DagCase> dag_cases(size_t count, uint64_t salt) {
  std::mt19937_64 rng(0x5eed0000 + salt);
  auto uniform = [&](uint64_t lo, uint64_t hi) { return std::uniform_int_distribution<uint64_t>(lo, hi)(rng); };
  static const uint64_t image_alignments[] = {1, 256, 4096, 65536, 3000};
  static const uint64_t buffer_alignments[] = {1, 16, 256, 100};
  static const FrameSize frames[] = {{1280, 720}, {1920, 1080}, {64, 64}, {1, 1}, {3840, 2160}, {333, 517}};
  std::vector<DagCase> cases;
  for (size_t k = 0; k < count; ++k) {
    DagCase c;
    c.dag.nodes = k % 10 == 0 ? 300 : k % 3 == 0 ? uniform(5, 300) : uniform(5, 60);
    c.dag.dead_fraction = static_cast<double>(uniform(0, 8)) / 10;
    c.dag.history_fraction = k % 4 == 0 ? 0 : static_cast<double>(uniform(0, 10)) / 10;
    c.dag.window = uniform(1, 24);
    c.dag.seed = salt * 100000 + k + 1;
    c.options.frame = frames[uniform(0, std::size(frames) - 1)];
    c.options.alias.enabled = uniform(0, 5) != 0;
    c.options.alias.image_alignment = image_alignments[uniform(0, std::size(image_alignments) - 1)];
    c.options.alias.buffer_alignment = buffer_alignments[uniform(0, std::size(buffer_alignments) - 1)];
    cases.push_back(c);
  }
  return cases;
}

}  // namespace lg::test
