// Graph edits as pure functions: ids, positions, nodes, links, params, copy and paste.
#include "editor/graph_edits.h"

#include <gtest/gtest.h>

#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg::editor {
namespace {

Graph load(const char* name) {
  Diagnostics d;
  std::optional<Graph> g = load_graph_file(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/" + name, d);
  EXPECT_TRUE(g) << d.to_string();
  return g.value_or(Graph{});
}

TEST(GraphEdits, IdsComeFromTheTypeAndNeverRepeat) {
  Graph g = load("default.json");
  EXPECT_EQ(unique_node_id(g, "post.bloom"), "bloom");
  EXPECT_EQ(unique_node_id(g, "post.tonemap"), "tonemap2");
  const std::string a = add_node(g, "post.tonemap", {10, 20});
  EXPECT_EQ(a, "tonemap2");
  EXPECT_EQ(unique_node_id(g, "post.tonemap"), "tonemap3");
  EXPECT_EQ(node_position(g, a), (Position{10, 20}));
}

TEST(GraphEdits, RemovingNodesTakesTheirLinksOutputsAndPositions) {
  Graph g = load("default.json");
  g.outputs.push_back({{"gtao", "ao"}, {}});
  remove_nodes(g, {"gtao"});
  EXPECT_EQ(find_node(g, "gtao"), nullptr);
  for (const GraphLink& l : g.links) EXPECT_TRUE(l.from.node != "gtao" && l.to.node != "gtao");
  EXPECT_TRUE(g.outputs.empty());
  EXPECT_FALSE(node_position(g, "gtao"));
  EXPECT_TRUE(node_position(g, "sky"));
}

TEST(GraphEdits, LinksAreAddedOnceAndRemoved) {
  Graph g = load("minimal.json");
  const size_t n = g.links.size();
  add_link(g, {"gbuf", "gbuffer"}, {"tonemap", "color"});
  add_link(g, {"gbuf", "gbuffer"}, {"tonemap", "color"});
  EXPECT_EQ(g.links.size(), n + 1);
  EXPECT_TRUE(has_link(g, {"gbuf", "gbuffer"}, {"tonemap", "color"}));
  remove_link(g, {"gbuf", "gbuffer"}, {"tonemap", "color"});
  EXPECT_EQ(g.links.size(), n);
}

TEST(GraphEdits, ParamsAreSetAndResetToTheDefault) {
  Graph g = load("default.json");
  set_param(g, "tonemap", "exposure", JsonValue(1.5));
  EXPECT_EQ(*find_node(g, "tonemap")->params.find("exposure"), JsonValue(1.5));
  set_param(g, "tonemap", "exposure", JsonValue());
  EXPECT_EQ(find_node(g, "tonemap")->params.find("exposure"), nullptr);
  EXPECT_NE(find_node(g, "tonemap")->params.find("curve"), nullptr);
}

// A preset sets every param it names; the node then matches it, and matches none after one of
// those params changes.
TEST(GraphEdits, APresetSetsItsParamsAndTheNodeMatchesIt) {
  Graph g = load("post.json");
  const NodeSchema* schema = builtin_registry().find("post.bloom");
  ASSERT_TRUE(schema);
  ASSERT_GE(schema->presets.size(), 2u);
  const ParamPreset& last = schema->presets.back();
  apply_preset(g, "bloom", *schema, last);
  for (const auto& [param, value] : last.values)
    EXPECT_EQ(*find_node(g, "bloom")->params.find(schema->params[param].name), value);
  EXPECT_EQ(matching_preset(*find_node(g, "bloom"), *schema), int(schema->presets.size()) - 1);
  const std::string& first_param = schema->params[last.values.front().first].name;
  set_param(g, "bloom", first_param, JsonValue(last.values.front().second.as_number() + 1));
  EXPECT_EQ(matching_preset(*find_node(g, "bloom"), *schema), -1);
}

TEST(GraphEdits, PasteGivesFreshIdsKeepsInnerLinksAndOffsets) {
  Graph g = load("default.json");
  const Graph part = extract_nodes(g, {"sky", "sh", "ibl"});
  EXPECT_EQ(part.nodes.size(), 3u);
  EXPECT_EQ(part.links.size(), 2u);  // sky.cube -> sh.env and sh.sh -> ibl.sh
  const size_t links = g.links.size();
  const std::vector<std::string> added = paste_nodes(g, part, {40, 40});
  ASSERT_EQ(added.size(), 3u);
  EXPECT_EQ(added[0], "sky2");
  EXPECT_EQ(g.links.size(), links + 2);
  EXPECT_TRUE(has_link(g, {"sky2", "cube"}, {"sh2", "env"}));
  const Position before = *node_position(g, "sky"), after = *node_position(g, "sky2");
  EXPECT_EQ(after[0], before[0] + 40);
  EXPECT_EQ(after[1], before[1] + 40);
  EXPECT_EQ(find_node(g, "sky2")->params, find_node(g, "sky")->params);
}

TEST(GraphEdits, UnknownEditorKeysSurviveMoves) {
  Graph g = load("minimal.json");
  g.editor.set("notes", JsonValue("keep me"));
  set_node_position(g, "light", {300.4, -12.6});
  EXPECT_EQ(*g.editor.find("notes"), JsonValue("keep me"));
  EXPECT_EQ(node_position(g, "light"), (Position{300, -13}));
}

}  // namespace
}  // namespace lg::editor
