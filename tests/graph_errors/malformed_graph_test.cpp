// Malformed graph files, one case each: the error must say what is wrong, at the right line
// and column, with the JSON pointer where one exists. Cases run the whole front end (parse,
// resolve, validate, lower) with the real node schemas.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/limits.h"
#include "nodes/builtin_schemas.h"

namespace lg {
namespace {

struct Case {
  const char* name;
  std::string text;
  const char* message;  // a substring of the expected error
  uint32_t line, column;
  const char* pointer;  // expected JSON pointer, "" when the error is about the whole text
};

// A small valid graph with {NODES}, {LINKS} and {OUTPUTS} to fill in; line 1 is '{'.
std::string graph(const std::string& nodes, const std::string& links = "", const std::string& outputs = "\"t.color\"") {
  return "{\n"
         "  \"format\": \"lumagraph/1\",\n"
         "  \"nodes\": [\n" +
         nodes +
         "\n  ],\n"
         "  \"links\": [\n" +
         links +
         "\n  ],\n"
         "  \"outputs\": [" +
         outputs + "]\n}\n";
}
// Nodes start on line 4; links on line 6 + number of node lines.
const std::string sky_tonemap =
    "    { \"id\": \"g\", \"type\": \"scene.gbuffer\" },\n"
    "    { \"id\": \"l\", \"type\": \"lighting.deferred\" },\n"
    "    { \"id\": \"t\", \"type\": \"post.tonemap\" }";
const std::string chain_links =
    "    { \"from\": \"g.gbuffer\", \"to\": \"l.gbuffer\" },\n"
    "    { \"from\": \"l.color\", \"to\": \"t.color\" }";

std::vector<Case> cases() {
  std::vector<Case> c = {
      // JSON syntax
      {"empty file", "", "the file is empty", 1, 1, ""},
      {"only spaces", "   \n  ", "the file is empty", 2, 3, ""},
      {"truncated", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [", "expected a value", 3, 13, ""},
      {"missing comma", "{\n  \"format\": \"lumagraph/1\"\n  \"nodes\": []\n}", "expected ',' or '}'", 3, 3, ""},
      {"unclosed string", "{\n  \"format\": \"lumagraph/1\n}", "unterminated string", 2, 25, ""},
      {"trailing comma in array", "{\n  \"nodes\": [1, 2, ]\n}", "trailing comma before ']'", 2, 19, ""},
      {"trailing comma in object", "{\n  \"format\": \"lumagraph/1\",\n}", "trailing comma before '}'", 3, 1, ""},
      {"comment", "{\n  // nodes\n  \"nodes\": []\n}", "comments are not allowed", 2, 3, ""},
      {"single quotes", "{\n  'format': 'lumagraph/1'\n}", "double quotes", 2, 3, ""},
      {"trailing garbage", "{ \"format\": \"lumagraph/1\", \"nodes\": [] }\nxyz", "after the end of the JSON document", 2, 1, ""},
      {"NaN literal", "{\n  \"nodes\": [ { \"params\": { \"x\": NaN } } ]\n}", "NaN is not valid JSON", 2, 33, ""},
      {"Infinity literal", "{\n  \"x\": -Infinity\n}", "no infinity", 2, 8, ""},
      {"number out of range", "{\n  \"x\": 1e999\n}", "out of range", 2, 8, ""},
      {"leading zero", "{\n  \"x\": 012\n}", "leading zeros", 2, 8, ""},
      {"python literal", "{\n  \"x\": True\n}", "JSON spells them true, false, null", 2, 8, ""},
      {"duplicate key", "{\n  \"format\": \"lumagraph/1\",\n  \"format\": \"lumagraph/1\"\n}", "duplicate key \"format\" (first at line 2", 3, 3, ""},
      {"bad escape", "{\n  \"name\": \"a\\qb\"\n}", "invalid escape \\q", 2, 13, ""},
      {"lone surrogate", "{\n  \"name\": \"\\udc00\"\n}", "unpaired UTF-16 surrogate", 2, 12, ""},
      {"invalid UTF-8", "{\n  \"name\": \"\xff\"\n}", "invalid UTF-8", 2, 12, ""},
      {"deep nesting", "{\n  \"editor\": " + std::string(100, '[') + std::string(100, ']') + "\n}", "nesting is deeper than 64 levels", 2, 76, ""},
      // Structure
      {"root is an array", "[\n]", "expected a graph object", 1, 1, ""},
      {"no format", "{\n  \"nodes\": []\n}", "missing \"format\"", 1, 1, ""},
      {"newer format", "{\n  \"format\": \"lumagraph/2\",\n  \"nodes\": []\n}", "unsupported format 'lumagraph/2'; this build reads lumagraph/1 (the file may come from a newer version)", 2, 13, "/format"},
      {"foreign format", "{\n  \"format\": \"gltf\",\n  \"nodes\": []\n}", "unsupported format 'gltf'", 2, 13, "/format"},
      {"no nodes", "{\n  \"format\": \"lumagraph/1\"\n}", "missing \"nodes\"", 1, 1, ""},
      {"misspelt top-level key", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [],\n  \"link\": []\n}", "unknown key 'link'; did you mean 'links'?", 4, 11, "/link"},
      {"nodes not an array", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": {}\n}", "expected an array, found an object", 3, 12, "/nodes"},
      {"node not an object", graph("    42"), "expected a node object", 4, 5, "/nodes/0"},
      {"node without id", graph("    { \"type\": \"post.tonemap\" }"), "node has no \"id\"", 4, 5, "/nodes/0"},
      {"node without type", graph("    { \"id\": \"t\" }"), "node has no \"type\"", 4, 5, "/nodes/0"},
      {"id with a dot", graph("    { \"id\": \"a.b\", \"type\": \"post.tonemap\" }"), "invalid node id 'a.b'", 4, 13, "/nodes/0/id"},
      {"id too long", graph("    { \"id\": \"" + std::string(65, 'x') + "\", \"type\": \"post.tonemap\" }"), "invalid node id", 4, 13, "/nodes/0/id"},
      {"misspelt node key", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"parms\": {} }"), "unknown key 'parms'; did you mean 'params'?", 4, 51, "/nodes/0/parms"},
      {"params not an object", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": [] }"), "expected an object of params", 4, 52, "/nodes/0/params"},
      {"duplicate id", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\" },\n    { \"id\": \"t\", \"type\": \"post.bloom\" }"), "duplicate node id 't' (first used at line 4, column 13)", 5, 13, "/nodes/1/id"},
      {"link not node.port", graph(sky_tonemap, "    { \"from\": \"g\", \"to\": \"l.gbuffer\" }"), "expected \"node.port\"", 9, 15, "/links/0/from"},
      {"link with two dots", graph(sky_tonemap, "    { \"from\": \"g.gbuffer.depth\", \"to\": \"l.gbuffer\" }"), "expected \"node.port\" (for example \"sky.cube\"), found \"g.gbuffer.depth\"", 9, 15, "/links/0/from"},
      {"link without to", graph(sky_tonemap, "    { \"from\": \"g.gbuffer\" }"), "link has no \"to\"", 9, 5, "/links/0"},
      {"enormous array", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [],\n  \"editor\": [" + [] {
         std::string items;
         for (size_t k = 0; k <= limits::max_array_items; ++k) items += "0,";
         return items + "0";
       }() + "]\n}", "an array has more than 262144 items", 4, 524302, ""},
      // Against the registry
      {"unknown node type", graph("    { \"id\": \"t\", \"type\": \"post.tonemapper\" }"), "unknown node type 'post.tonemapper'; did you mean 'post.tonemap'?", 4, 26, "/nodes/0/type"},
      {"unknown node type, no guess", graph("    { \"id\": \"t\", \"type\": \"fancy.thing\" }"), "unknown node type 'fancy.thing'; `lumagraph nodes` lists the known types", 4, 26, "/nodes/0/type"},
      {"unknown param", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": { \"exposur\": 1 } }"), "has no param 'exposur'; did you mean 'exposure'?", 4, 65, "/nodes/0/params/exposur"},
      {"unknown output port", graph(sky_tonemap, "    { \"from\": \"g.gbufer\", \"to\": \"l.gbuffer\" },\n    { \"from\": \"l.color\", \"to\": \"t.color\" }"), "node 'g' (scene.gbuffer) has no output 'gbufer'; did you mean 'gbuffer'?", 9, 15, "/links/0/from"},
      {"unknown input port", graph(sky_tonemap, "    { \"from\": \"g.gbuffer\", \"to\": \"l.gbuf\" },\n    { \"from\": \"l.color\", \"to\": \"t.color\" }"), "node 'l' (lighting.deferred) has no input 'gbuf'", 9, 34, "/links/0/to"},
      {"output used as input", graph(sky_tonemap, "    { \"from\": \"g.gbuffer\", \"to\": \"l.color\" },\n    { \"from\": \"l.color\", \"to\": \"t.color\" }"), "'color' is an output", 9, 34, "/links/0/to"},
      {"link to unknown node", graph(sky_tonemap, chain_links + ",\n    { \"from\": \"sky.cube\", \"to\": \"t.color\" }"), "no node with id 'sky'", 11, 15, "/links/2/from"},
      {"input linked twice", graph(sky_tonemap, chain_links + ",\n    { \"from\": \"l.color\", \"to\": \"t.color\" }"), "input 't.color' is already linked from 'l.color' (line 10)", 11, 32, "/links/2/to"},
      {"cube into 2D texture", graph(sky_tonemap + ",\n    { \"id\": \"s\", \"type\": \"env.sky\" }", "    { \"from\": \"g.gbuffer\", \"to\": \"l.gbuffer\" },\n    { \"from\": \"s.cube\", \"to\": \"t.color\" }"), "cannot link s.cube (cube:hdr) to t.color (texture2d:hdr): a cube map cannot feed a 2D texture", 11, 31, "/links/1/to"},
      {"mask into hdr", graph(sky_tonemap + ",\n    { \"id\": \"a\", \"type\": \"occlusion.ssao\" }", "    { \"from\": \"g.gbuffer\", \"to\": \"a.gbuffer\" },\n    { \"from\": \"a.ao\", \"to\": \"t.color\" }"), "the formats differ: texture2d:mask is not texture2d:hdr", 11, 29, "/links/1/to"},
      {"missing required input", graph(sky_tonemap, "    { \"from\": \"l.color\", \"to\": \"t.color\" }"), "node 'l' (lighting.deferred) needs its input 'gbuffer' (gbuffer) linked", 5, 5, "/nodes/1"},
      {"cycle", graph("    { \"id\": \"a\", \"type\": \"post.bloom\" },\n    { \"id\": \"b\", \"type\": \"post.bloom\" },\n    { \"id\": \"t\", \"type\": \"post.tonemap\" }",
                      "    { \"from\": \"a.color\", \"to\": \"b.color\" },\n    { \"from\": \"b.color\", \"to\": \"a.color\" },\n    { \"from\": \"b.color\", \"to\": \"t.color\" }"),
       "cycle: b -> a -> b; a loop is only allowed through a history input", 9, 32, "/links/0/to"},
      {"dangling output", graph(sky_tonemap, chain_links, "\"t.colour\""), "node 't' (post.tonemap) has no output 'colour'; did you mean 'color'?", 12, 15, "/outputs/0"},
      {"output names unknown node", graph(sky_tonemap, chain_links, "\"x.color\""), "no node with id 'x'", 12, 15, "/outputs/0"},
      {"asks for nothing", graph(sky_tonemap, chain_links, ""), "the graph asks for nothing", 1, 1, "/outputs"},
      // Params
      {"param out of range (float)", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": { \"exposure\": 40 } }", "", "\"t.color\""), "param 'exposure' of node 't' (post.tonemap) must be a number from -20 to 20 (EV)", 4, 66, "/nodes/0/params/exposure"},
      {"param out of range (int)", graph("    { \"id\": \"s\", \"type\": \"env.sh_project\", \"params\": { \"order\": 7 } }"), "must be an integer from 1 to 4", 4, 65, "/nodes/0/params/order"},
      {"fraction for an int", graph("    { \"id\": \"s\", \"type\": \"env.sh_project\", \"params\": { \"order\": 2.5 } }"), "must be an integer from 1 to 4", 4, 65, "/nodes/0/params/order"},
      {"string for a float", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": { \"exposure\": \"bright\" } }"), "must be a number from -20 to 20", 4, 66, "/nodes/0/params/exposure"},
      {"enum value not listed", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": { \"curve\": \"filmic\" } }"), "must be one of \"aces_fitted\", \"neutral\", \"clamp\"", 4, 63, "/nodes/0/params/curve"},
      {"bool as number", graph("    { \"id\": \"g\", \"type\": \"scene.gbuffer\", \"params\": { \"cull_backfaces\": 1 } }"), "must be true or false", 4, 73, "/nodes/0/params/cull_backfaces"},
      {"vector too short", graph("    { \"id\": \"s\", \"type\": \"env.sky\", \"params\": { \"sun_direction\": [0, 1] } }"), "must be an array of 3 numbers from -1 to 1", 4, 66, "/nodes/0/params/sun_direction"},
      {"vector component out of range", graph("    { \"id\": \"s\", \"type\": \"env.sky\", \"params\": { \"sun_direction\": [0, 2, 0] } }"), "must be an array of 3 numbers from -1 to 1", 4, 66, "/nodes/0/params/sun_direction"},
      {"null param", graph("    { \"id\": \"t\", \"type\": \"post.tonemap\", \"params\": { \"exposure\": null } }"), "must be a number", 4, 66, "/nodes/0/params/exposure"},
  };
  return c;
}

// What gtest prints for a case: its name, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class MalformedGraph : public testing::TestWithParam<Case> {};

TEST_P(MalformedGraph, ReportsWhatWhereAndWhy) {
  const Case& c = GetParam();
  Diagnostics diagnostics("broken.json");
  std::optional<Graph> graph = parse_graph_text(c.text, diagnostics);
  CompileResult result;
  if (graph) result = compile(*graph, builtin_registry(), {}, diagnostics);
  EXPECT_FALSE(result.plan);
  bool found = false;
  for (const Diagnostic& d : diagnostics.items()) {
    if (d.message.find(c.message) == std::string::npos) continue;
    found = true;
    EXPECT_EQ(d.pos.line, c.line) << d.to_string();
    EXPECT_EQ(d.pos.column, c.column) << d.to_string();
    EXPECT_EQ(d.pointer, c.pointer) << d.to_string();
    EXPECT_EQ(d.to_string().rfind("broken.json:" + std::to_string(c.line) + ":", 0), 0u);
  }
  EXPECT_TRUE(found) << "expected \"" << c.message << "\", got:\n" << diagnostics.to_string();
}

INSTANTIATE_TEST_SUITE_P(Cases, MalformedGraph, testing::ValuesIn(cases()), [](const auto& info) {
  std::string name = info.param.name;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
});

TEST(MalformedGraphAll, ReportsEveryErrorInTheFile) {
  // Three independent mistakes: all three are reported, in file order.
  std::string text = graph(
      "    { \"id\": \"t\", \"type\": \"post.tonemapper\" },\n"
      "    { \"id\": \"b\", \"type\": \"post.bloom\", \"params\": { \"intensity\": -1 } },\n"
      "    { \"id\": \"s\", \"type\": \"env.sh_project\", \"params\": { \"order\": 9 } }",
      "", "\"b.color\"");
  Diagnostics diagnostics("broken.json");
  std::optional<Graph> graph = parse_graph_text(text, diagnostics);
  ASSERT_TRUE(graph);
  EXPECT_FALSE(compile(*graph, builtin_registry(), {}, diagnostics).plan);
  diagnostics.sort_by_position();
  std::vector<uint32_t> lines;
  for (const Diagnostic& d : diagnostics.items()) lines.push_back(d.pos.line);
  // b also lacks its required input (line 5) and s lacks its environment (line 6).
  EXPECT_EQ(lines, (std::vector<uint32_t>{4, 5, 5, 6, 6})) << diagnostics.to_string();
}

}  // namespace
}  // namespace lg
