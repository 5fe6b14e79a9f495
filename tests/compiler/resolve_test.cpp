// Phase 2, resolve, alone: every param gets a value (the file's or the schema default), every
// link and output is bound to port indices, and unknown names are reported with a suggestion.
#include "graph/compiler/resolve.h"

#include <gtest/gtest.h>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

using test::load_example;

int node_index(const Graph& g, std::string_view id) {
  for (size_t n = 0; n < g.nodes.size(); ++n)
    if (g.nodes[n].id == id) return static_cast<int>(n);
  return -1;
}

TEST(CompilerResolve, ParamsNotWrittenGetTheSchemaDefaultAndWrittenOnesTheFileValue) {
  Graph g = load_example("examples/default.json");
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  ASSERT_FALSE(d.has_errors()) << d.to_string();
  ASSERT_EQ(r.nodes.size(), g.nodes.size());

  for (size_t n = 0; n < g.nodes.size(); ++n) {
    const NodeSchema& s = *r.nodes[n].schema;
    EXPECT_EQ(s.type, g.nodes[n].type);
    ASSERT_EQ(r.nodes[n].params.size(), s.params.size()) << g.nodes[n].id;
    for (size_t p = 0; p < s.params.size(); ++p) {
      const JsonValue* written = g.nodes[n].params.find(s.params[p].name);
      // Not a copy: the resolved param points at the file's value or at the schema's default.
      const JsonValue* expected = written ? written : &s.params[p].default_value;
      EXPECT_EQ(r.nodes[n].params[p], expected) << g.nodes[n].id << "." << s.params[p].name;
    }
  }
  // Spot checks with values: sh writes order 2 and leaves window_target at its default 0.1.
  const ResolvedNode& sh = r.nodes[node_index(g, "sh")];
  EXPECT_EQ(sh.param(sh.schema->find_param("order")).as_number(), 2);
  EXPECT_DOUBLE_EQ(sh.param(sh.schema->find_param("window_target")).as_number(), 0.1);
  EXPECT_TRUE(sh.param(sh.schema->find_param("convolve_cosine")).as_bool());  // the file says true; default false
  const ResolvedNode& gbuf = r.nodes[node_index(g, "gbuf")];
  EXPECT_DOUBLE_EQ(gbuf.param(gbuf.schema->find_param("resolution_scale")).as_number(), 1.0);
}

TEST(CompilerResolve, LinksAndOutputsAreBoundToPortIndices) {
  Graph g = load_example("examples/post.json");
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  ASSERT_FALSE(d.has_errors()) << d.to_string();
  ASSERT_EQ(r.links.size(), g.links.size());
  for (size_t k = 0; k < r.links.size(); ++k) {
    const ResolvedLink& l = r.links[k];
    const GraphLink& gl = g.links[l.source];
    EXPECT_EQ(g.nodes[l.from_node].id, gl.from.node);
    EXPECT_EQ(g.nodes[l.to_node].id, gl.to.node);
    EXPECT_EQ(r.nodes[l.from_node].schema->outputs[l.from_port].name, gl.from.port);
    EXPECT_EQ(r.nodes[l.to_node].schema->inputs[l.to_port].name, gl.to.port);
    EXPECT_EQ(r.nodes[l.to_node].input_link[l.to_port], static_cast<int>(k)) << gl.to.text();
    EXPECT_FALSE(l.history) << "post.json has no history input";
  }
  // Inputs without a link stay -1: ibl.irradiance, ibl.ao and ibl.bent_normals are optional.
  const ResolvedNode& ibl = r.nodes[node_index(g, "ibl")];
  EXPECT_EQ(ibl.input_link[ibl.schema->find_input("irradiance")], -1);
  EXPECT_EQ(ibl.input_link[ibl.schema->find_input("ao")], -1);
  EXPECT_GE(ibl.input_link[ibl.schema->find_input("direct")], 0);

  ASSERT_EQ(r.outputs.size(), 1u);
  EXPECT_EQ(r.outputs[0].first, node_index(g, "ibl"));
  EXPECT_EQ(r.outputs[0].second, ibl.schema->find_output("color"));
}

TEST(CompilerResolve, OnlyLinksIntoHistoryInputsAreMarkedHistory) {
  Graph g = load_example("examples/default.json");
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  ASSERT_FALSE(d.has_errors()) << d.to_string();
  int history = 0;
  for (const auto& l : r.links) {
    bool expected = g.links[l.source].to.text() == "gtao.history";
    EXPECT_EQ(l.history, expected) << g.links[l.source].to.text();
    history += l.history;
  }
  EXPECT_EQ(history, 1);
}

TEST(CompilerResolve, UnknownNamesAreReportedWithTheClosestKnownName) {
  Graph g = load_example("examples/minimal.json");
  test::node_named(g, "tonemap").type = "post.tonemapp";
  test::node_named(g, "gbuf").params.set("resolution_scal", 0.5);
  test::add_link(g, "gbuf.gbufer", "light.gbuffer");  // also a second link into light.gbuffer
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  std::string text = d.to_string();
  EXPECT_NE(text.find("unknown node type 'post.tonemapp'; did you mean 'post.tonemap'?"), std::string::npos) << text;
  EXPECT_NE(text.find("has no param 'resolution_scal'; did you mean 'resolution_scale'?"), std::string::npos) << text;
  EXPECT_NE(text.find("has no output 'gbufer'; did you mean 'gbuffer'?"), std::string::npos) << text;
  EXPECT_EQ(r.nodes[node_index(g, "tonemap")].schema, nullptr);
  // A broken reference is bound to nothing: one resolved link fewer than in the file.
  EXPECT_LT(r.links.size(), g.links.size());
}

TEST(CompilerResolve, LinkingFromAnInputSaysItIsAnInput) {
  Graph g = load_example("examples/minimal.json");
  test::add_link(g, "light.gbuffer", "tonemap.color");
  Diagnostics d;
  resolve(g, builtin_registry(), d);
  EXPECT_NE(d.to_string().find("has no output 'gbuffer'; 'gbuffer' is an input"), std::string::npos) << d.to_string();
}

TEST(CompilerResolve, ASecondLinkIntoOneInputIsAnError) {
  Graph g = load_example("examples/minimal.json");
  test::add_link(g, "gbuf.gbuffer", "light.gbuffer");
  Diagnostics d;
  ResolvedGraph r = resolve(g, builtin_registry(), d);
  EXPECT_NE(d.to_string().find("input 'light.gbuffer' is already linked from 'gbuf.gbuffer'"), std::string::npos)
      << d.to_string();
  EXPECT_EQ(r.links.size(), g.links.size() - 1);
}

}  // namespace
}  // namespace lg
