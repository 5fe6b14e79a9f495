// The plan depends on what the graph says, not on how the file happens to list it: shuffling
// the nodes and the links (ids unchanged) gives a byte-identical JSON plan. Editors reorder
// files; a build cache and a diff of plans must not see a change.
#include <gtest/gtest.h>

#include "graph/json_reader.h"
#include "graph/json_writer.h"
#include "graph/plan_format.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

std::string plan_json(const Graph& g, const Registry& registry, const CompileOptions& options = {}) {
  return write_json(plan_to_json(test::compile_ok(g, registry, options)));
}

// Empty when equal, else the first line that differs with its number: plans are long.
std::string first_difference(const std::string& a, const std::string& b) {
  if (a == b) return {};
  size_t line = 1, start = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()) && a[k] == b[k]; ++k)
    if (a[k] == '\n') ++line, start = k + 1;
  auto line_of = [&](const std::string& s) { return s.substr(start, s.find('\n', start) - start); };
  return "line " + std::to_string(line) + ":\n  expected: " + line_of(a) + "\n  got:      " + line_of(b);
}

// The file's text with its "nodes" and "links" arrays shuffled, read back as a new graph.
Graph shuffled_file(const Graph& g, uint64_t seed) {
  JsonValue root = graph_to_json(g);
  std::mt19937_64 rng(seed);
  for (const char* key : {"nodes", "links"})
    for (auto& [name, value] : root.members())
      if (name == key) std::shuffle(value.items().begin(), value.items().end(), rng);
  Graph out = test::parse_text(write_json(root));
  out.file = g.file;
  return out;
}

TEST(CompilerDeterminism, ShuffledExamplesGiveByteIdenticalPlans) {
  int compared = 0;
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths()) {
      CompileOptions o;
      o.scene = test::load_scene(scene);
      Graph g = test::load_example(path);
      std::string expected = plan_json(g, builtin_registry(), o);
      for (uint64_t seed = 1; seed <= 8; ++seed) {
        EXPECT_EQ(first_difference(expected, plan_json(test::shuffled(g, seed), builtin_registry(), o)), "")
            << path << " " << scene << " seed " << seed;
        EXPECT_EQ(first_difference(expected, plan_json(shuffled_file(g, seed), builtin_registry(), o)), "")
            << path << " " << scene << " file seed " << seed;
        compared += 2;
      }
    }
  EXPECT_EQ(compared, static_cast<int>(test::example_paths().size() * test::scene_paths().size() * 16));
  EXPECT_GE(compared, 3 * 4 * 16);
}

TEST(CompilerDeterminism, ShuffledRandomDagsGiveByteIdenticalPlans) {
  int compared = 0;
  for (const auto& c : test::dag_cases(200, 6)) {
    Graph g = test::make_random_dag(c.dag);
    if (c.dag.seed % 2) g = test::with_history_from_elsewhere(std::move(g), c.dag.seed);
    std::string expected = plan_json(g, test::synthetic_registry(), c.options);
    for (uint64_t seed : {c.dag.seed, c.dag.seed + 7919}) {
      std::string diff =
          first_difference(expected, plan_json(test::shuffled(g, seed), test::synthetic_registry(), c.options));
      EXPECT_EQ(diff, "") << c.describe() << " shuffle " << seed;
      if (!diff.empty()) return;  // the first case is enough to debug from
      ++compared;
    }
  }
  EXPECT_EQ(compared, 400);
}

TEST(CompilerDeterminism, CullReasonDoesNotDependOnLinkOrder) {
  // One G-buffer feeds the depth inputs of two depth-of-field nodes that a pinhole camera
  // bypasses: its culling reason must not depend on which link the file lists last.
  Graph g = test::load_example("examples/post.json");
  test::add_node(g, "dof_depth", "scene.gbuffer");
  test::add_node(g, "dof2", "post.dof");
  test::remove_link_to(g, "dof.gbuffer");
  test::remove_link_to(g, "bloom.color");
  test::add_link(g, "dof_depth.gbuffer", "dof.gbuffer");
  test::add_link(g, "dof_depth.gbuffer", "dof2.gbuffer");
  test::add_link(g, "dof.color", "dof2.color");
  test::add_link(g, "dof2.color", "bloom.color");
  std::string expected = plan_json(g, builtin_registry());
  for (uint64_t seed = 1; seed <= 16; ++seed)
    EXPECT_EQ(first_difference(expected, plan_json(test::shuffled(g, seed), builtin_registry())), "")
        << "seed " << seed;
  // Both bypassed users are named, in id order.
  Plan plan = test::compile_ok(g, builtin_registry());
  EXPECT_EQ(test::plan_node(plan, "dof_depth")->state, NodeState::Kind::culled);
  EXPECT_EQ(test::plan_node(plan, "dof_depth")->reason, "only 'dof' and 'dof2' use it, and those nodes are bypassed");
}

TEST(CompilerDeterminism, CompilingTwiceGivesTheSamePlan) {
  Graph g = test::load_example("examples/default.json");
  EXPECT_EQ(plan_json(g, builtin_registry()), plan_json(g, builtin_registry()));
  EXPECT_EQ(plan_to_text(test::compile_ok(g, builtin_registry())),
            plan_to_text(test::compile_ok(g, builtin_registry())));
}

}  // namespace
}  // namespace lg
