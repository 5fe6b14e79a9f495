// The plan depends on what the graph says, never on the order the file says it in: shuffling
// nodes and links gives a byte-identical plan.
#include <gtest/gtest.h>

#include "graph/json_writer.h"
#include "graph/plan_format.h"
#include "tests/plan_checks/plan_fixtures.h"

namespace lg::test {
namespace {

std::string plan_text(const Graph& graph, const Registry& registry, const CompileOptions& options = {}) {
  return write_json(plan_to_json(compile_or_throw(graph, registry, options)));
}

// The first line where two texts differ, for a readable failure.
std::string first_difference(const std::string& a, const std::string& b) {
  size_t at = 0, line = 1;
  while (at < a.size() && at < b.size() && a[at] == b[at]) line += a[at++] == '\n';
  if (at == a.size() && at == b.size()) return {};
  auto line_of = [&](const std::string& s) {
    size_t begin = s.rfind('\n', at == 0 ? 0 : at - 1);
    begin = begin == std::string::npos ? 0 : begin + 1;
    return s.substr(begin, s.find('\n', at) - begin);
  };
  return "line " + std::to_string(line) + ": '" + line_of(a) + "' vs '" + line_of(b) + "'";
}

TEST(PlanDeterminism, ShuffledExamplesGiveTheSamePlan) {
  for (const auto& file : example_files()) {
    Graph graph = load_example(file);
    std::string expected = plan_text(graph, builtin_registry());
    for (uint64_t seed = 1; seed <= 20; ++seed)
      ASSERT_EQ(first_difference(plan_text(shuffled(graph, seed), builtin_registry()), expected), "")
          << file << " shuffle " << seed;
  }
}

TEST(PlanDeterminism, ShuffledRandomGraphsGiveTheSamePlan) {
  for (const DagCase& c : dag_cases(200)) {
    Graph graph = make_random_dag(c.dag);
    std::string expected = plan_text(graph, synthetic_registry(), c.options);
    for (uint64_t seed = 1; seed <= 3; ++seed)
      ASSERT_EQ(first_difference(plan_text(shuffled(graph, seed), synthetic_registry(), c.options), expected), "")
          << "nodes " << c.dag.nodes << " seed " << c.dag.seed << " shuffle " << seed;
  }
}

TEST(PlanDeterminism, RenamingANodeChangesOnlyNames) {
  // A control: the comparison above is sensitive to content, not just always equal.
  Graph graph = load_example("examples/minimal.json");
  std::string before = plan_text(graph, builtin_registry());
  graph.nodes[2].params.set("exposure", 1.5);
  EXPECT_NE(plan_text(graph, builtin_registry()), before);
}

}  // namespace
}  // namespace lg::test
