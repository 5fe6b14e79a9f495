// Live validation: the examples compile; errors name the node they are about.
#include "editor/validation.h"

#include <gtest/gtest.h>

#include "editor/graph_edits.h"
#include "graph/graph_io.h"

namespace lg::editor {
namespace {

Graph load(const std::string& name) {
  Diagnostics d;
  std::optional<Graph> g = load_graph_file(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/" + name, d);
  EXPECT_TRUE(g) << d.to_string();
  return g.value_or(Graph{});
}

TEST(Validation, ExamplesCompileToPlans) {
  for (const char* name : {"minimal.json", "default.json", "post.json"}) {
    const Validation v = validate_graph(load(name));
    EXPECT_TRUE(v.plan) << name;
    EXPECT_FALSE(v.has_errors()) << name;
  }
}

TEST(Validation, ErrorsPointAtTheirNode) {
  Graph g = load("default.json");
  set_param(g, "tonemap", "exposure", JsonValue(99));
  remove_link(g, {"gbuf", "gbuffer"}, {"light", "gbuffer"});
  const Validation v = validate_graph(g);
  EXPECT_FALSE(v.plan);
  std::set<std::string> nodes;
  for (const Problem& p : v.problems) nodes.insert(p.node);
  EXPECT_TRUE(nodes.count("tonemap"));
  EXPECT_TRUE(nodes.count("light"));
}

TEST(Validation, PointersMapToNodes) {
  const Graph g = load("minimal.json");
  EXPECT_EQ(node_of_pointer(g, "/nodes/2/params/exposure"), "tonemap");
  EXPECT_EQ(node_of_pointer(g, "/links/0/to"), "light");
  EXPECT_EQ(node_of_pointer(g, "/links/0/from"), "gbuf");
  EXPECT_EQ(node_of_pointer(g, "/links/9/to"), "");
  EXPECT_EQ(node_of_pointer(g, "/name"), "");
  EXPECT_EQ(param_of_pointer("/nodes/2/params/exposure"), "exposure");
  EXPECT_EQ(param_of_pointer("/nodes/2/params/size/1"), "size");
  EXPECT_EQ(param_of_pointer("/nodes/2/type"), "");
}

}  // namespace
}  // namespace lg::editor
