// Phase 3, validate, alone: its node order is topological over every non-history link and the
// same whatever order the file lists nodes and links in; bad params, links and cycles are errors.
#include "graph/compiler/validate.h"

#include <gtest/gtest.h>

#include <map>

#include "graph/compiler/resolve.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

struct Validated {
  std::optional<CachedVector<int>> order;
  std::string errors;
};

Validated run_validate(const Graph& g, const Registry& registry) {
  Diagnostics d;
  ResolvedGraph r = resolve(g, registry, d);
  auto order = validate(r, {}, d);
  return {order, d.to_string()};
}

// Every non-history link goes from an earlier node to a later one, and each node appears once.
void expect_topological(const Graph& g, const Registry& registry, const CachedVector<int>& order) {
  ASSERT_EQ(order.size(), g.nodes.size());
  std::vector<int> position(g.nodes.size(), -1);
  for (size_t k = 0; k < order.size(); ++k) {
    ASSERT_EQ(position[order[k]], -1) << "node listed twice";
    position[order[k]] = static_cast<int>(k);
  }
  std::map<std::string, int> index;
  for (size_t n = 0; n < g.nodes.size(); ++n) index[g.nodes[n].id] = static_cast<int>(n);
  for (const auto& l : g.links) {
    int from = index.at(l.from.node), to = index.at(l.to.node);
    const NodeSchema* s = registry.find(g.nodes[to].type);
    bool history = s->inputs[s->find_input(l.to.port)].history;
    if (!history) {
      EXPECT_LT(position[from], position[to]) << l.from.text() << " -> " << l.to.text();
    }
  }
}

std::vector<std::string> ids_in_order(const Graph& g, const CachedVector<int>& order) {
  std::vector<std::string> ids;
  for (int n : order) ids.push_back(g.nodes[n].id);
  return ids;
}

TEST(CompilerValidate, OrderIsTopologicalAndIgnoresTheFileOrderOnTheExamples) {
  for (const auto& path : test::example_paths()) {
    SCOPED_TRACE(path);
    Graph g = test::load_example(path);
    Validated v = run_validate(g, builtin_registry());
    ASSERT_TRUE(v.order) << v.errors;
    expect_topological(g, builtin_registry(), *v.order);
    auto expected = ids_in_order(g, *v.order);
    for (uint64_t seed = 1; seed <= 25; ++seed) {
      Graph s = test::shuffled(g, seed);
      Validated w = run_validate(s, builtin_registry());
      ASSERT_TRUE(w.order) << w.errors;
      expect_topological(s, builtin_registry(), *w.order);
      EXPECT_EQ(ids_in_order(s, *w.order), expected) << "seed " << seed;
    }
  }
}

TEST(CompilerValidate, OrderIsTopologicalAndIgnoresTheFileOrderOnRandomDags) {
  int checked = 0;
  for (const auto& c : test::dag_cases(200, 1)) {
    Graph g = test::make_random_dag(c.dag);
    Validated v = run_validate(g, test::synthetic_registry());
    ASSERT_TRUE(v.order) << c.describe() << "\n" << v.errors;
    expect_topological(g, test::synthetic_registry(), *v.order);
    Graph s = test::shuffled(g, c.dag.seed);
    Validated w = run_validate(s, test::synthetic_registry());
    ASSERT_TRUE(w.order) << w.errors;
    EXPECT_EQ(ids_in_order(s, *w.order), ids_in_order(g, *v.order)) << c.describe();
    ++checked;
  }
  EXPECT_EQ(checked, 200);
}

TEST(CompilerValidate, IndependentNodesComeInIdOrder) {
  // Three sources feed a blend; with nothing else to order them, ids decide: a, b, c.
  Graph g;
  test::add_node(g, "c", "test.source");
  test::add_node(g, "b", "test.source");
  test::add_node(g, "a", "test.source");
  test::add_node(g, "mix", "test.blend");
  test::add_node(g, "out", "test.sink");
  test::add_link(g, "c.out", "mix.a");
  test::add_link(g, "a.out", "mix.b");
  test::add_link(g, "b.out", "mix.c");
  test::add_link(g, "mix.out", "out.color");
  Validated v = run_validate(g, test::synthetic_registry());
  ASSERT_TRUE(v.order) << v.errors;
  EXPECT_EQ(ids_in_order(g, *v.order), (std::vector<std::string>{"a", "b", "c", "mix", "out"}));
}

TEST(CompilerValidate, ALoopWithoutAHistoryInputIsACycleError) {
  Graph g;
  test::add_node(g, "src", "test.source");
  test::add_node(g, "x", "test.blend");
  test::add_node(g, "y", "test.filter");
  test::add_node(g, "out", "test.sink");
  test::add_link(g, "src.out", "x.a");
  test::add_link(g, "y.out", "x.b");  // y -> x -> y
  test::add_link(g, "x.out", "y.a");
  test::add_link(g, "y.out", "out.color");
  Validated v = run_validate(g, test::synthetic_registry());
  EXPECT_FALSE(v.order);
  EXPECT_NE(v.errors.find("cycle: "), std::string::npos) << v.errors;
  EXPECT_NE(v.errors.find("a loop is only allowed through a history input"), std::string::npos) << v.errors;
  EXPECT_TRUE(v.errors.find("x -> y -> x") != std::string::npos || v.errors.find("y -> x -> y") != std::string::npos)
      << v.errors;
}

TEST(CompilerValidate, BadParamsTypesAndMissingInputsAreAllReported) {
  Graph g = test::load_example("examples/default.json");
  test::node_named(g, "sh").params.set("order", 9);              // out of range
  test::node_named(g, "tonemap").params.set("curve", "filmic");  // not in the enum
  test::node_named(g, "gtao").params.set("radius", "far");       // not a number
  test::remove_link_to(g, "light.gbuffer");                      // a required input
  Validated v = run_validate(g, builtin_registry());
  EXPECT_FALSE(v.order);
  for (const char* expected :
       {"param 'order' of node 'sh' (env.sh_project) must be an integer from 1 to 4",
        "param 'curve' of node 'tonemap' (post.tonemap) must be one of \"aces_fitted\", \"neutral\", \"clamp\"",
        "param 'radius' of node 'gtao' (occlusion.gtao) must be a number from 0.01 to 100 (m)",
        "node 'light' (lighting.deferred) needs its input 'gbuffer' (gbuffer) linked"})
    EXPECT_NE(v.errors.find(expected), std::string::npos) << expected << "\nin:\n" << v.errors;
}

TEST(CompilerValidate, IncompatibleLinkTypesAreErrors) {
  Graph g = test::load_example("examples/minimal.json");
  test::add_node(g, "sky", "env.sky");
  test::remove_link_to(g, "tonemap.color");
  test::add_link(g, "sky.cube", "tonemap.color");
  Validated v = run_validate(g, builtin_registry());
  EXPECT_FALSE(v.order);
  EXPECT_NE(v.errors.find("cannot link sky.cube (cube:hdr) to tonemap.color (texture2d:hdr)"), std::string::npos)
      << v.errors;
}

TEST(CompilerValidate, AGraphThatAsksForNothingIsAnError) {
  Graph g;
  test::add_node(g, "src", "test.source");
  Validated v = run_validate(g, test::synthetic_registry());
  EXPECT_FALSE(v.order);
  EXPECT_NE(v.errors.find("the graph asks for nothing"), std::string::npos) << v.errors;
}

// A schema's "less_than" names another number param, and its defaults must be in that order;
// the graph-side refusal is in tests/parse/malformed_graph_test.cpp.
TEST(CompilerValidate, SchemaParamOrderRulesAreChecked) {
  auto schema = [](const std::string& low, const std::string& high) {
    return R"({ "type": "test.ordered", "doc": "d", "passes": [ { "name": "p", "queue": "compute", "uses": {} } ], "params": [
      { "name": "low", "type": "float", "default": )" +
           low + R"(, "less_than": "high", "doc": "d" },
      { "name": "high", "type": "float", "default": )" +
           high + R"(, "doc": "d" },
      { "name": "mode", "type": "enum", "default": "a", "values": ["a"], "doc": "d" } ] })";
  };
  Registry registry;
  Diagnostics ok;
  ASSERT_TRUE(registry.add_schema(schema("1", "2"), ok)) << ok.to_string();
  const NodeSchema& s = *registry.find("test.ordered");
  EXPECT_EQ(s.params[0].less_than, 1);
  EXPECT_EQ(s.params[1].less_than, -1);

  Diagnostics unordered;
  EXPECT_FALSE(Registry().add_schema(schema("2", "2"), unordered));
  EXPECT_NE(unordered.to_string().find("the default must be below 'high''s default"), std::string::npos)
      << unordered.to_string();
  for (const char* other : {"\"nothing\"", "\"low\"", "\"mode\"", "3"}) {
    std::string text = schema("1", "2");
    text.replace(text.find("\"high\", \"doc\""), 6, other);
    Diagnostics d;
    EXPECT_FALSE(Registry().add_schema(text, d)) << other;
    EXPECT_NE(d.to_string().find("expected the name of another float or int param"), std::string::npos)
        << other << ": " << d.to_string();
  }
}

}  // namespace
}  // namespace lg
