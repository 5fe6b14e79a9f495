// Graph files in and out: every example loads, saves and reloads to the same graph, saving is
// deterministic to the byte, and what the editor keeps under "editor" (keys this build has
// never heard of, nested as deep as it likes) survives a round trip untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "graph/graph_io.h"
#include "graph/json_reader.h"
#include "graph/limits.h"
#include "parse_test_support.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

// examples/*.json (not the scene summaries in examples/scenes), as absolute paths, sorted.
std::vector<std::string> example_graphs() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(LUMAGRAPH_SOURCE_DIR) / "examples"))
    if (e.is_regular_file() && e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

Graph load_ok(const std::string& path) {
  Diagnostics d;
  auto g = load_graph_file(path, d);
  EXPECT_TRUE(g.has_value()) << d.to_string();
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  return g.value_or(Graph{});
}

Graph parse_ok(std::string_view text) {
  Diagnostics d;
  auto g = parse_graph_text(text, d);
  EXPECT_TRUE(g.has_value()) << d.to_string();
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  return g.value_or(Graph{});
}

JsonValue json_ok(std::string_view text) {
  Diagnostics d;
  auto v = read_json(text, d);
  EXPECT_TRUE(v.has_value()) << d.to_string();
  return v.value_or(JsonValue{});
}

TEST(ParseGraphIo, ThereAreExamplesToTest) {
  // Guards the loops below against passing vacuously if the folder moves.
  EXPECT_GE(example_graphs().size(), 3u);
}

TEST(ParseGraphIo, EachExampleLoadsSavesAndReloadsToAnEqualGraph) {
  for (const std::string& path : example_graphs()) {
    SCOPED_TRACE(path);
    Graph loaded = load_ok(path);
    EXPECT_EQ(loaded.file, path);
    EXPECT_FALSE(loaded.nodes.empty());
    TempDir dir;
    std::string saved_path = dir.file("saved.json");
    std::string error;
    ASSERT_TRUE(save_graph_file(loaded, saved_path, &error)) << error;
    Graph reloaded = load_ok(saved_path);
    EXPECT_EQ(graph_to_text(reloaded), graph_to_text(loaded));
    EXPECT_EQ(read_text(saved_path), graph_to_text(loaded));

    // Field by field too, so a bug shared by writer and reader cannot hide behind the text.
    EXPECT_EQ(reloaded.name, loaded.name);
    ASSERT_EQ(reloaded.nodes.size(), loaded.nodes.size());
    for (size_t k = 0; k < loaded.nodes.size(); ++k) {
      EXPECT_EQ(reloaded.nodes[k].id, loaded.nodes[k].id);
      EXPECT_EQ(reloaded.nodes[k].type, loaded.nodes[k].type);
      EXPECT_EQ(reloaded.nodes[k].params, loaded.nodes[k].params);
    }
    ASSERT_EQ(reloaded.links.size(), loaded.links.size());
    for (size_t k = 0; k < loaded.links.size(); ++k) {
      EXPECT_EQ(reloaded.links[k].from.text(), loaded.links[k].from.text());
      EXPECT_EQ(reloaded.links[k].to.text(), loaded.links[k].to.text());
    }
    ASSERT_EQ(reloaded.outputs.size(), loaded.outputs.size());
    for (size_t k = 0; k < loaded.outputs.size(); ++k)
      EXPECT_EQ(reloaded.outputs[k].port.text(), loaded.outputs[k].port.text());
    EXPECT_EQ(reloaded.editor, loaded.editor);
  }
}

TEST(ParseGraphIo, SavingLosesNothingTheExampleSaid) {
  // The saved JSON holds the same content as the hand-written file (layout aside). Lists
  // the file left out are written empty, so they compare as empty.
  for (const std::string& path : example_graphs()) {
    SCOPED_TRACE(path);
    JsonValue original = json_ok(read_text(path));
    for (const char* list : {"links", "outputs"})
      if (!original.find(list)) original.set(list, JsonValue::array());
    JsonValue saved = json_ok(graph_to_text(load_ok(path)));
    for (const auto& [key, value] : original.members()) {
      ASSERT_NE(saved.find(key), nullptr) << key;
      EXPECT_EQ(*saved.find(key), value) << key;
    }
    EXPECT_EQ(saved.size(), original.size());
  }
}

TEST(ParseGraphIo, SavingAnExampleTwiceGivesIdenticalBytes) {
  for (const std::string& path : example_graphs()) {
    SCOPED_TRACE(path);
    TempDir dir;
    std::string error;
    Graph g = load_ok(path);
    ASSERT_TRUE(save_graph_file(g, dir.file("a.json"), &error)) << error;
    ASSERT_TRUE(save_graph_file(g, dir.file("b.json"), &error)) << error;
    EXPECT_EQ(read_text(dir.file("a.json")), read_text(dir.file("b.json")));
    // And saving what was saved reproduces it: the saved form is a fixed point.
    Graph again = load_ok(dir.file("a.json"));
    ASSERT_TRUE(save_graph_file(again, dir.file("c.json"), &error)) << error;
    EXPECT_EQ(read_text(dir.file("c.json")), read_text(dir.file("a.json")));
  }
}

const char* editor_graph = R"({
  "format": "lumagraph/1",
  "name": "editor keys",
  "nodes": [ { "id": "g", "type": "scene.gbuffer" } ],
  "outputs": ["g.gbuffer"],
  "editor": {
    "zoom": 1.250,
    "positions": { "g": [0, 0] },
    "x-plugin": {
      "deep": { "list": [1, { "k": null, "nested": [[true], "é\n"] }], "n": 1.50e0 },
      "empty": {}
    },
    "notes": "keep \"me\" \ud83d\ude00",
    "a-later-key": []
  }
})";

TEST(ParseGraphIo, UnknownEditorKeysSurviveARoundTripNestedAndInOrder) {
  Graph g = parse_ok(editor_graph);
  JsonValue original_editor = *json_ok(editor_graph).find("editor");
  std::string saved = graph_to_text(g);
  Graph back = parse_ok(saved);
  EXPECT_EQ(back.editor, original_editor);
  std::vector<std::string> keys;
  for (const auto& [key, value] : back.editor.members()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"zoom", "positions", "x-plugin", "notes", "a-later-key"}));
  // Numbers are written as the file wrote them, however deep.
  EXPECT_NE(saved.find("\"zoom\": 1.250"), std::string::npos) << saved;
  EXPECT_NE(saved.find("\"n\": 1.50e0"), std::string::npos) << saved;
}

TEST(ParseGraphIo, ParamsKeepTheirTextAndOrder) {
  Graph g = parse_ok(R"({"format": "lumagraph/1", "nodes": [
    {"id": "t", "type": "post.tonemap", "params": {"exposure": -0.50, "curve": "neutral"}},
    {"id": "a", "type": "scene.gbuffer", "params": {}}
  ], "outputs": ["t.color"]})");
  std::string saved = graph_to_text(g);
  size_t exposure = saved.find("\"exposure\": -0.50");
  size_t curve = saved.find("\"curve\": \"neutral\"");
  ASSERT_NE(exposure, std::string::npos) << saved;
  ASSERT_NE(curve, std::string::npos) << saved;
  EXPECT_LT(exposure, curve);
  // Nodes stay in file order (t before a), not sorted by id.
  EXPECT_LT(saved.find("\"id\": \"t\""), saved.find("\"id\": \"a\""));
}

TEST(ParseGraphIo, ParseRecordsWhereEachPartWasWritten) {
  Graph g = parse_ok(
      "{\n"
      "  \"format\": \"lumagraph/1\",\n"
      "  \"nodes\": [\n"
      "    { \"id\": \"g\", \"type\": \"scene.gbuffer\" },\n"
      "    { \"id\": \"l\", \"type\": \"lighting.deferred\" }\n"
      "  ],\n"
      "  \"links\": [ { \"from\": \"g.gbuffer\", \"to\": \"l.gbuffer\" } ],\n"
      "  \"outputs\": [\"l.color\"]\n"
      "}\n");
  ASSERT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(g.nodes[1].pos.line, 5u);
  EXPECT_EQ(g.nodes[1].pos.column, 5u);
  EXPECT_EQ(g.nodes[1].type_pos.column, 26u);
  ASSERT_EQ(g.links.size(), 1u);
  EXPECT_EQ(g.links[0].from.node, "g");
  EXPECT_EQ(g.links[0].from.port, "gbuffer");
  EXPECT_EQ(g.links[0].from_pos.line, 7u);
  EXPECT_EQ(g.links[0].from_pos.column, 24u);
  EXPECT_EQ(g.links[0].to_pos.column, 43u);
  ASSERT_EQ(g.outputs.size(), 1u);
  EXPECT_EQ(g.outputs[0].pos.line, 8u);
  EXPECT_EQ(g.outputs[0].pos.column, 15u);
}

TEST(ParseGraphIo, SavingIntoAMissingFolderFails) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(save_graph_file(parse_ok(editor_graph), dir.file("missing/g.json"), &error));
  EXPECT_NE(error.find("missing"), std::string::npos) << error;
}

TEST(ParseGraphIo, LoadingAMissingFileNamesIt) {
  TempDir dir;
  Diagnostics d;
  EXPECT_FALSE(load_graph_file(dir.file("absent.json"), d));
  ASSERT_EQ(d.items().size(), 1u);
  EXPECT_EQ(d.items()[0].file, dir.file("absent.json"));
  EXPECT_EQ(d.items()[0].message, "cannot open the file: No such file or directory");
}

TEST(ParseGraphIo, IdsAreOneTo64LettersDigitsUnderscoresOrDashes) {
  EXPECT_TRUE(is_valid_id("A-z_09"));
  EXPECT_TRUE(is_valid_id(std::string(limits::max_id_length, 'x')));
  EXPECT_FALSE(is_valid_id(std::string(limits::max_id_length + 1, 'x')));
  EXPECT_FALSE(is_valid_id(""));
  for (const char* bad : {"a.b", "a b", "a/b", "\xC3\xA9", "a\n", "a:b"}) EXPECT_FALSE(is_valid_id(bad)) << bad;
}

}  // namespace
}  // namespace lg
