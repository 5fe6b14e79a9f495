// Malformed graph files, one table row each: the error must say what is wrong, at the line and
// column of the offending text, with the JSON pointer of the offending value where there is
// one. Each row runs the whole front end a user runs (parse, then compile against the real
// node schemas), so a message that only a later phase produces is found too. Positions in the
// table were counted by hand from the raw text, not copied from the program's output.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "graph/limits.h"
#include "nodes/builtin_schemas.h"
#include "parse_test_support.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::TempDir;
using parse_test::write_text;

struct Case {
  const char* name;
  std::string text;
  const char* message;  // a substring of the expected error's message
  uint32_t line, column;
  const char* pointer;     // the expected JSON pointer; "" for errors about the text itself
  bool in_folder = false;  // loaded from graphs/graph.json in a temporary folder (see below)
};

// The valid graph most rows are a small edit of (line numbers on the right):
//
//   {                                                       1
//     "format": "lumagraph/1",                              2
//     "nodes": [                                            3
//       { "id": "g", "type": "scene.gbuffer" },             4
//       { "id": "l", "type": "lighting.deferred" },         5
//       { "id": "t", "type": "post.tonemap" }               6
//     ],                                                    7
//     "links": [                                            8
//       { "from": "g.gbuffer", "to": "l.gbuffer" },         9
//       { "from": "l.color", "to": "t.color" }              10
//     ],                                                    11
//     "outputs": ["t.color"]                                12
//   }                                                       13
//
// In a node line the id's value is at column 13 and the type's at 26; in a link line "from"'s
// value is at 15 and "to"'s at 15 + (length of the quoted from) + 8; outputs start at 15.
const char* base_graph = R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" },
    { "id": "l", "type": "lighting.deferred" },
    { "id": "t", "type": "post.tonemap" }
  ],
  "links": [
    { "from": "g.gbuffer", "to": "l.gbuffer" },
    { "from": "l.color", "to": "t.color" }
  ],
  "outputs": ["t.color"]
}
)";

// base_graph with the text of one line (1-based) replaced.
std::string base_with(int line, const std::string& replacement) {
  std::string text = base_graph;
  size_t begin = 0;
  for (int k = 1; k < line; ++k) begin = text.find('\n', begin) + 1;
  size_t end = text.find('\n', begin);
  return text.substr(0, begin) + replacement + text.substr(end);
}

// The graph the path rows edit: line 4 sets env.load's path, whose value starts at column 60.
std::string load_graph(const std::string& node_line) {
  return R"({
  "format": "lumagraph/1",
  "nodes": [
)" + node_line + R"(
    { "id": "sh", "type": "env.sh_project" }
  ],
  "links": [ { "from": "env.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
}
)";
}
std::string load_path(const std::string& path) {
  return load_graph(R"(    { "id": "env", "type": "env.load", "params": { "path": ")" + path + R"(" } },)");
}

// A G-buffer lit and metered by post.exposure 'x' with `params` (an object's members) on line 6,
// where the params object's members start at column 55.
std::string exposure_graph(const std::string& params) {
  return R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" },
    { "id": "l", "type": "lighting.deferred" },
    { "id": "x", "type": "post.exposure", "params": { )" +
         params + R"( } }
  ],
  "links": [ { "from": "g.gbuffer", "to": "l.gbuffer" }, { "from": "l.color", "to": "x.color" } ],
  "outputs": ["x.exposure"]
}
)";
}

std::vector<Case> cases() {
  const std::string array_of_zeros = [] {
    std::string s;
    for (size_t k = 0; k <= limits::max_array_items; ++k) s += k ? ",0" : "0";
    return s;
  }();
  const std::string too_many_nodes = [] {
    std::string s;
    for (size_t k = 0; k <= limits::max_nodes; ++k) s += k ? ",0" : "0";
    return s;
  }();

  return {
      // --- JSON syntax: the reader stops at the first mistake ---------------------------------
      {"empty file", "", "the file is empty", 1, 1, ""},
      {"truncated after an open bracket", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [",
       "unexpected end of the file; expected a value", 3, 13, ""},
      {"truncated inside a node", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [\n    { \"id\": \"g\", \"type\"",
       "expected ':' after the key \"type\", found the end of the file", 4, 24, ""},
      {"missing comma between nodes", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" }
    { "id": "t", "type": "post.tonemap" }
  ]
})",
       "expected ',' or ']' in an array, found '{'", 5, 5, ""},
      {"missing comma between keys", R"({
  "format": "lumagraph/1"
  "nodes": []
})",
       "expected ',' or '}' in an object, found '\"'", 3, 3, ""},
      {"unclosed string before a line break", R"({
  "format": "lumagraph/1,
  "nodes": []
})",
       "unterminated string (a line break inside a string must be written \\n)", 2, 26, ""},
      {"unclosed string at the end", "{\n  \"format\": \"lumagraph/1\",\n  \"name\": \"my graph",
       "unterminated string", 3, 11, ""},
      {"trailing garbage", "{ \"format\": \"lumagraph/1\", \"nodes\": [] }\n]",
       "unexpected text after the end of the JSON document", 2, 1, ""},
      {"trailing comma", R"({
  "format": "lumagraph/1",
  "nodes": [],
  "links": [
    { "from": "a.b", "to": "c.d" },
  ]
})",
       "trailing comma before ']'", 6, 3, ""},
      {"comment", R"({
  "format": "lumagraph/1", // version
  "nodes": []
})",
       "comments are not allowed in JSON", 2, 28, ""},
      {"NaN literal", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "exposure": NaN } })"),
       "NaN is not valid JSON; use a finite number", 6, 66, ""},
      {"1e999", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "exposure": 1e999 } })"),
       "number 1e999 is out of range", 6, 66, ""},
      {"duplicate key", R"({
  "format": "lumagraph/1",
  "nodes": [],
  "nodes": []
})",
       "duplicate key \"nodes\" (first at line 3, column 3)", 4, 3, ""},
      // Root object, editor object, then '[' number k is level k + 2: level 65 is the 63rd,
      // and the first '[' is at column 19.
      {"deep nesting", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [],\n  \"editor\": {\"x\": " +
                           std::string(100, '[') + std::string(100, ']') + "}\n}",
       "nesting is deeper than 64 levels", 4, 19 + 62, ""},
      // Item k of the array (from 0) is at column 13 + 2k; item 262,144 is one too many.
      {"enormous array", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [" + array_of_zeros + "]\n}",
       "an array has more than 262144 items", 3, 13 + 2 * limits::max_array_items, ""},

      // --- The graph's structure ---------------------------------------------------------------
      {"root is an array", "[\n  {}\n]", "expected a graph object {\"format\": \"lumagraph/1\", ...}, found an array", 1, 1, ""},
      {"root is a string", "  \"lumagraph/1\"", "found a string", 1, 3, ""},
      {"no format", "{\n  \"nodes\": []\n}", "missing \"format\": \"lumagraph/1\"", 1, 1, ""},
      {"format version 2", "{\n  \"format\": \"lumagraph/2\",\n  \"nodes\": []\n}",
       "unsupported format 'lumagraph/2'; this build reads lumagraph/1 (the file may come from a newer version)", 2, 13,
       "/format"},
      {"format is a number", "{\n  \"format\": 1,\n  \"nodes\": []\n}", "expected the string \"lumagraph/1\"", 2, 13, "/format"},
      {"misspelt top-level key", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [],\n  \"ouputs\": []\n}",
       "unknown key 'ouputs'; did you mean 'outputs'?", 4, 13, "/ouputs"},
      {"unknown top-level key", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [],\n  \"version\": 2\n}",
       "unknown key 'version'; expected format, name, nodes, links, outputs, editor", 4, 14, "/version"},
      {"no nodes", "{\n  \"format\": \"lumagraph/1\"\n}", "missing \"nodes\": [...]", 1, 1, ""},
      {"nodes is an object", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": {}\n}", "expected an array, found an object", 3, 12,
       "/nodes"},
      {"links is a string", base_with(8, R"(  "links": "g.gbuffer", "x": [)"), "expected an array, found a string", 8, 12, "/links"},
      {"name is a number", base_with(2, R"(  "name": 7, "format": "lumagraph/1",)"), "expected a string, found a number", 2, 11, "/name"},
      {"editor is an array", base_with(12, R"(  "outputs": ["t.color"], "editor": [])"), "expected an object, found an array", 12, 37,
       "/editor"},
      // 65,537 nodes is within the JSON limits but over the graph's.
      {"too many nodes", "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [" + too_many_nodes + "]\n}",
       "too many nodes: 65537 (the limit is 65536)", 3, 12, "/nodes"},

      // --- Nodes -------------------------------------------------------------------------------
      {"node is a string", base_with(4, R"(    "g",)"), "expected a node object {\"id\": ..., \"type\": ...}, found a string", 4, 5,
       "/nodes/0"},
      {"node without id", base_with(4, R"(    { "type": "scene.gbuffer" },)"), "node has no \"id\"", 4, 5, "/nodes/0"},
      {"node without type", base_with(4, R"(    { "id": "g" },)"), "node has no \"type\"", 4, 5, "/nodes/0"},
      {"id is a number", base_with(4, R"(    { "id": 7, "type": "scene.gbuffer" },)"), "expected a string, found a number", 4, 13,
       "/nodes/0/id"},
      {"id with a space", base_with(4, R"(    { "id": "sky map", "type": "scene.gbuffer" },)"),
       "invalid node id 'sky map': use 1 to 64 letters, digits, '_' or '-'", 4, 13, "/nodes/0/id"},
      {"id with a dot", base_with(4, R"(    { "id": "g.1", "type": "scene.gbuffer" },)"), "invalid node id 'g.1'", 4, 13,
       "/nodes/0/id"},
      {"id too long", base_with(4, "    { \"id\": \"" + std::string(65, 'g') + "\", \"type\": \"scene.gbuffer\" },"),
       "invalid node id: it has 65 characters; use 1 to 64 letters, digits, '_' or '-'", 4, 13, "/nodes/0/id"},
      {"empty id", base_with(4, R"(    { "id": "", "type": "scene.gbuffer" },)"), "invalid node id: it has 0 characters", 4, 13,
       "/nodes/0/id"},
      {"duplicate id", base_with(5, R"(    { "id": "g", "type": "lighting.deferred" },)"),
       "duplicate node id 'g' (first used at line 4, column 13)", 5, 13, "/nodes/1/id"},
      {"misspelt node key", base_with(4, R"(    { "id": "g", "type": "scene.gbuffer", "param": {} },)"),
       "unknown key 'param'; did you mean 'params'?", 4, 52, "/nodes/0/param"},
      {"params is an array", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": [0] })"),
       "expected an object of params, found an array", 6, 52, "/nodes/2/params"},

      // --- Node types and params, checked against the schemas ----------------------------------
      {"unknown type, near a known one", base_with(6, R"(    { "id": "t", "type": "post.tonmap" })"),
       "unknown node type 'post.tonmap'; did you mean 'post.tonemap'?", 6, 26, "/nodes/2/type"},
      {"unknown type", base_with(6, R"(    { "id": "t", "type": "fx.sparkles" })"),
       "unknown node type 'fx.sparkles'; `lumagraph nodes` lists the known types", 6, 26, "/nodes/2/type"},
      {"unknown param, near a known one", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "exposur": 1 } })"),
       "node 't' (post.tonemap) has no param 'exposur'; did you mean 'exposure'?", 6, 65, "/nodes/2/params/exposur"},
      {"unknown param", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "gamma": 2.2 } })"),
       "node 't' (post.tonemap) has no param 'gamma'; its params are: exposure, curve", 6, 63, "/nodes/2/params/gamma"},
      {"float param is a string", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "exposure": "+1" } })"),
       "param 'exposure' of node 't' (post.tonemap) must be a number from -20 to 20 (EV)", 6, 66, "/nodes/2/params/exposure"},
      {"float param above its range", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "exposure": 20.5 } })"),
       "param 'exposure' of node 't' (post.tonemap) must be a number from -20 to 20 (EV)", 6, 66, "/nodes/2/params/exposure"},
      {"float param not among its values", base_with(6, R"(    { "id": "t", "type": "gi.irradiance_volume", "params": { "resolution_scale": 0.3 } })"),
       "param 'resolution_scale' of node 't' (gi.irradiance_volume) must be a number among 1, 0.5, 0.333333, 0.25", 6, 82,
       "/nodes/2/params/resolution_scale"},
      {"int param not among its values", base_with(6, R"(    { "id": "t", "type": "gi.reflection_capture", "params": { "face_size": 48 } })"),
       "param 'face_size' of node 't' (gi.reflection_capture) must be an integer among 4, 8, 16, 32, 64, 128, 256, 512, 1024 (texels)", 6, 76,
       "/nodes/2/params/face_size"},
      {"enum value not in the list", base_with(6, R"(    { "id": "t", "type": "post.tonemap", "params": { "curve": "filmic" } })"),
       R"(param 'curve' of node 't' (post.tonemap) must be one of "aces_fitted", "neutral", "clamp")", 6, 63,
       "/nodes/2/params/curve"},
      // post.exposure's schema orders low_percent below high_percent ("less_than"): the error is
      // at the value the graph wrote, low_percent's when both are, with both values.
      {"params out of their schema's order", exposure_graph(R"("low_percent": 96, "high_percent": 95)"),
       "param 'low_percent' of node 'x' (post.exposure) must be below its param 'high_percent': low_percent 96 is "
       "not below high_percent 95", 6, 70, "/nodes/2/params/low_percent"},
      {"a param out of order with another's default", exposure_graph(R"("high_percent": 40)"),
       "must be below its param 'high_percent': low_percent 50 (its default) is not below high_percent 40", 6, 71,
       "/nodes/2/params/high_percent"},
      // env.sh_project's params object: a param's value is at 66 for "order", 74 for
      // "window_target", 67 for "window" and 76 for "convolve_cosine".
      {"int param above its range", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "order": 9 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       "param 'order' of node 'sh' (env.sh_project) must be an integer from 1 to 4", 5, 66, "/nodes/1/params/order"},
      {"int param below its range", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "order": 0 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       "param 'order' of node 'sh' (env.sh_project) must be an integer from 1 to 4", 5, 66, "/nodes/1/params/order"},
      {"int param not an integer", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "order": 2.5 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       "param 'order' of node 'sh' (env.sh_project) must be an integer from 1 to 4", 5, 66, "/nodes/1/params/order"},
      {"float param below its range", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "window_target": -0.1 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       "param 'window_target' of node 'sh' (env.sh_project) must be a number from 0 to 1", 5, 74,
       "/nodes/1/params/window_target"},
      {"enum param is not a string", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "window": 1 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       R"(must be one of "none", "hanning", "lanczos", "min_ringing")", 5, 67, "/nodes/1/params/window"},
      {"bool param is a number", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky" },
    { "id": "sh", "type": "env.sh_project", "params": { "convolve_cosine": 1 } }
  ],
  "links": [ { "from": "sky.cube", "to": "sh.env" } ],
  "outputs": ["sh.sh"]
})",
       "param 'convolve_cosine' of node 'sh' (env.sh_project) must be true or false", 5, 76,
       "/nodes/1/params/convolve_cosine"},
      // env.sky's "sun_direction" value is at column 68.
      {"vector param too short", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky", "params": { "sun_direction": [0, 1] } }
  ],
  "outputs": ["sky.cube"]
})",
       "param 'sun_direction' of node 'sky' (env.sky) must be an array of 3 numbers from -1 to 1", 4, 68,
       "/nodes/0/params/sun_direction"},
      {"vector param component out of range", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky", "params": { "sun_direction": [0, 2, 0] } }
  ],
  "outputs": ["sky.cube"]
})",
       "must be an array of 3 numbers from -1 to 1", 4, 68, "/nodes/0/params/sun_direction"},
      {"vector param is a number", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "sky", "type": "env.sky", "params": { "sun_direction": 1 } }
  ],
  "outputs": ["sky.cube"]
})",
       "must be an array of 3 numbers from -1 to 1", 4, 68, "/nodes/0/params/sun_direction"},
      {"string param is a number", base_with(6, R"(    { "id": "o", "type": "output.display", "params": { "name": 3 } })") ,
       "param 'name' of node 'o' (output.display) must be a string", 6, 64, "/nodes/2/params/name"},

      // --- Links and outputs --------------------------------------------------------------------
      {"unknown output port", base_with(9, R"(    { "from": "g.gbufer", "to": "l.gbuffer" },)"),
       "node 'g' (scene.gbuffer) has no output 'gbufer'; did you mean 'gbuffer'?", 9, 15, "/links/0/from"},
      {"unknown input port", base_with(9, R"(    { "from": "g.gbuffer", "to": "l.gbuf" },)"),
       "node 'l' (lighting.deferred) has no input 'gbuf'; its inputs are: gbuffer", 9, 34, "/links/0/to"},
      {"an input used as an output", base_with(10, R"(    { "from": "l.gbuffer", "to": "t.color" })"),
       "node 'l' (lighting.deferred) has no output 'gbuffer'; 'gbuffer' is an input", 10, 15, "/links/1/from"},
      {"an output used as an input", base_with(9, R"(    { "from": "g.gbuffer", "to": "g.gbuffer" },)"),
       "node 'g' (scene.gbuffer) has no input 'gbuffer'; 'gbuffer' is an output", 9, 34, "/links/0/to"},
      {"node.port.component reference", base_with(9, R"(    { "from": "g.gbuffer.depth", "to": "l.gbuffer" },)"),
       R"(expected "node.port" (for example "sky.cube"), found "g.gbuffer.depth")", 9, 15, "/links/0/from"},
      {"reference without a port", base_with(10, R"(    { "from": "l.color", "to": "t" })"),
       R"(expected "node.port" (for example "sky.cube"), found "t")", 10, 32, "/links/1/to"},
      {"reference is a number", base_with(10, R"(    { "from": "l.color", "to": 2 })"), R"(expected "node.port", found a number)",
       10, 32, "/links/1/to"},
      {"link to an unknown node", base_with(10, R"(    { "from": "l.color", "to": "tm.color" })"),
       "no node with id 'tm'; did you mean 't'?", 10, 32, "/links/1/to"},
      {"link is a string", base_with(9, R"(    "g.gbuffer -> l.gbuffer",)"),
       R"(expected a link {"from": "node.port", "to": "node.port"}, found a string)", 9, 5, "/links/0"},
      {"link without to", base_with(10, R"(    { "from": "l.color" })"), "link has no \"to\"", 10, 5, "/links/1"},
      {"misspelt link key", base_with(10, R"(    { "form": "l.color", "to": "t.color" })"),
       "unknown key 'form'; did you mean 'from'?", 10, 15, "/links/1/form"},
      {"input linked twice", base_with(10, R"(    { "from": "l.color", "to": "t.color" },
    { "from": "l.color", "to": "t.color" })"),
       "input 't.color' is already linked from 'l.color' (line 10); an input takes one link", 11, 32, "/links/2/to"},
      {"cube map into a 2D texture", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "s", "type": "env.sky" },
    { "id": "t", "type": "post.tonemap" }
  ],
  "links": [
    { "from": "s.cube", "to": "t.color" }
  ],
  "outputs": ["t.color"]
})",
       "cannot link s.cube (cube:hdr) to t.color (texture2d:hdr): a cube map cannot feed a 2D texture", 8, 31, "/links/0/to"},
      {"mask into hdr", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" },
    { "id": "a", "type": "occlusion.gtao" },
    { "id": "t", "type": "post.tonemap" }
  ],
  "links": [
    { "from": "g.gbuffer", "to": "a.gbuffer" },
    { "from": "a.ao", "to": "t.color" }
  ],
  "outputs": ["t.color"]
})",
       "cannot link a.ao (texture2d:mask) to t.color (texture2d:hdr): the formats differ: texture2d:mask is not texture2d:hdr", 10,
       29, "/links/1/to"},
      {"G-buffer into a 2D texture", base_with(10, R"(    { "from": "g.gbuffer", "to": "t.color" })"),
       "cannot link g.gbuffer (gbuffer) to t.color (texture2d:hdr): a G-buffer cannot feed a 2D texture", 10, 34, "/links/1/to"},
      // Found by walking back from the first node (a) along its inputs; the error sits on the
      // link that closes the loop, and lists the loop in the direction data flows.
      {"cycle of two", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "a", "type": "post.bloom" },
    { "id": "b", "type": "post.bloom" }
  ],
  "links": [
    { "from": "a.color", "to": "b.color" },
    { "from": "b.color", "to": "a.color" }
  ],
  "outputs": ["b.color"]
})",
       "cycle: b -> a -> b; a loop is only allowed through a history input", 8, 32, "/links/0/to"},
      {"cycle of three", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "a", "type": "post.bloom" },
    { "id": "b", "type": "post.bloom" },
    { "id": "c", "type": "post.bloom" }
  ],
  "links": [
    { "from": "a.color", "to": "b.color" },
    { "from": "b.color", "to": "c.color" },
    { "from": "c.color", "to": "a.color" }
  ],
  "outputs": ["c.color"]
})",
       "cycle: b -> c -> a -> b; a loop is only allowed through a history input", 9, 32, "/links/0/to"},
      {"node feeding itself", R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "a", "type": "post.bloom" }
  ],
  "links": [
    { "from": "a.color", "to": "a.color" }
  ],
  "outputs": ["a.color"]
})",
       "cycle: a -> a; a loop is only allowed through a history input", 7, 32, "/links/0/to"},
      {"missing required input", base_with(9, ""), "node 'l' (lighting.deferred) needs its input 'gbuffer' (gbuffer) linked", 5, 5,
       "/nodes/1"},
      {"output names an unknown port", base_with(12, R"(  "outputs": ["t.colour"])"),
       "node 't' (post.tonemap) has no output 'colour'; did you mean 'color'?", 12, 15, "/outputs/0"},
      {"output names an unknown node", base_with(12, R"(  "outputs": ["tonemap.color"])"), "no node with id 'tonemap'", 12, 15,
       "/outputs/0"},
      {"output is not node.port", base_with(12, R"(  "outputs": ["t"])"), R"(expected "node.port" (for example "sky.cube"), found "t")",
       12, 15, "/outputs/0"},
      {"output is a number", base_with(12, R"(  "outputs": [0])"), R"(expected "node.port", found a number)", 12, 15, "/outputs/0"},
      {"no outputs", base_with(12, R"(  "outputs": [])"),
       "the graph asks for nothing: list ports under \"outputs\" or add an output node", 1, 1, "/outputs"},
      {"no outputs key", base_with(12, R"(  "name": "no outputs")"), "the graph asks for nothing", 1, 1, "/outputs"},

      // --- File paths, loaded from <tmp>/graphs/graph.json --------------------------------------
      {"path escapes the graph folder", load_path("../../etc/passwd"),
       "'../../etc/passwd' resolves to", 4, 60, "/nodes/0/params/path", true},
      {"path escapes to a real file", load_path("../outside/sky.hdr"), "outside the allowed asset roots", 4, 60,
       "/nodes/0/params/path", true},
      {"absolute path outside the roots", load_path("{OUTSIDE}"), "outside the allowed asset roots", 4, 60,
       "/nodes/0/params/path", true},
      {"absolute system path", load_path("/etc/passwd"),
       "param 'path' of node 'env': '/etc/passwd' resolves to /etc/passwd, outside the allowed asset roots", 4, 60,
       "/nodes/0/params/path", true},
      {"symbolic link out of the folder", load_path("assets/link.hdr"), "outside the allowed asset roots", 4, 60,
       "/nodes/0/params/path", true},
      {"path with the wrong extension", load_path("assets/day.png"),
       "param 'path' of node 'env': 'assets/day.png' has the extension '.png'; expected one of .hdr, .exr", 4, 60,
       "/nodes/0/params/path", true},
      {"path to a missing file", load_path("assets/night.hdr"), "'assets/night.hdr' does not exist (looked for ", 4, 60,
       "/nodes/0/params/path", true},
      {"empty path", load_path(""), "param 'path' of node 'env': the path is empty", 4, 60, "/nodes/0/params/path", true},
      {"path is a number", load_graph(R"(    { "id": "env", "type": "env.load", "params": { "path": 5 } },)"),
       "param 'path' of node 'env' (env.load) must be a string", 4, 60, "/nodes/0/params/path", true},
      // Left out, the path takes its default, sky.hdr, which this folder does not have.
      {"default path to a missing file", load_graph(R"(    { "id": "env", "type": "env.load" },)"),
       "param 'path' of node 'env' is not set, so its default is used: 'sky.hdr' does not exist", 4, 5, "/nodes/0", true},
  };
}

// <tmp>/graphs/graph.json holds the case; beside it assets/day.hdr, assets/day.png and
// assets/link.hdr (a symbolic link to <tmp>/outside/sky.hdr, outside the graph's folder).
std::string write_case_folder(const TempDir& dir, std::string text) {
  fs::path graphs = dir.path() / "graphs";
  std::string outside = (dir.path() / "outside" / "sky.hdr").string();
  write_text(outside, "#?RADIANCE\n");
  write_text((graphs / "assets" / "day.hdr").string(), "#?RADIANCE\n");
  write_text((graphs / "assets" / "day.png").string(), "\x89PNG");
  fs::create_symlink(outside, graphs / "assets" / "link.hdr");
  if (size_t at = text.find("{OUTSIDE}"); at != std::string::npos) text.replace(at, 9, outside);
  std::string path = (graphs / "graph.json").string();
  write_text(path, text);
  return path;
}

// What a user runs: parse (from text or a file) and, when that succeeds, compile.
Diagnostics front_end(const Case& c, const TempDir& dir, std::string* path = nullptr) {
  Diagnostics d;
  std::optional<Graph> graph;
  if (c.in_folder) {
    std::string file = write_case_folder(dir, c.text);
    if (path) *path = file;
    graph = load_graph_file(file, d);
  } else {
    graph = parse_graph_text(c.text, d);
  }
  if (graph) {
    CompileResult result = compile(*graph, builtin_registry(), CompileOptions{}, d);
    EXPECT_FALSE(result.plan.has_value()) << "compiled despite the mistake";
  }
  return d;
}

// Test listings and failures name the case, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ParseMalformedGraph : public testing::TestWithParam<Case> {};

TEST_P(ParseMalformedGraph, ReportsTheErrorWhereItIs) {
  const Case& c = GetParam();
  TempDir dir;
  std::string path;
  Diagnostics d = front_end(c, dir, &path);
  const Diagnostic* found = parse_test::find_message(d, c.message);
  ASSERT_NE(found, nullptr) << "no error containing: " << c.message << "\ngot:\n" << d.to_string();
  EXPECT_EQ(found->severity, Severity::error);
  EXPECT_EQ(found->pos.line, c.line) << found->to_string();
  EXPECT_EQ(found->pos.column, c.column) << found->to_string();
  EXPECT_EQ(found->pointer, c.pointer) << found->to_string();
  // Loops are reported as "cycle: a -> b -> a; ...", first word first, so tools can find them.
  if (std::string_view(c.message).starts_with("cycle:")) {
    EXPECT_TRUE(found->message.starts_with("cycle: ")) << found->message;
  }
  if (c.in_folder) {
    EXPECT_EQ(found->file, path);
  }
  // Every error in a graph file can be found in it: none is left without a line.
  for (const auto& other : d.items()) EXPECT_GT(other.pos.line, 0u) << other.to_string();
}

std::string case_name(const testing::TestParamInfo<Case>& info) {
  std::string out;
  for (const char* p = info.param.name; *p; ++p) out += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, ParseMalformedGraph, testing::ValuesIn(cases()), case_name);

TEST(ParseMalformedGraphTable, HasAtLeast45Cases) { EXPECT_GE(cases().size(), 45u); }

// --- Positive controls: the edits above are what breaks each graph ------------------------------

Diagnostics compile_text(const std::string& text, std::optional<Plan>* plan = nullptr) {
  Diagnostics d;
  auto graph = parse_graph_text(text, d);
  if (graph) {
    CompileResult result = compile(*graph, builtin_registry(), CompileOptions{}, d);
    if (plan) *plan = std::move(result.plan);
  }
  return d;
}

TEST(ParseMalformedGraphControl, TheBaseGraphCompiles) {
  std::optional<Plan> plan;
  Diagnostics d = compile_text(base_graph, &plan);
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  EXPECT_TRUE(plan.has_value());
}

TEST(ParseMalformedGraphControl, AHistoryBackEdgeIsLegal) {
  // gtao.ao feeds gtao.history: a loop, but through a history input, so no error.
  std::optional<Plan> plan;
  Diagnostics d = compile_text(R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" },
    { "id": "a", "type": "occlusion.gtao" }
  ],
  "links": [
    { "from": "g.gbuffer", "to": "a.gbuffer" },
    { "from": "a.ao", "to": "a.history" }
  ],
  "outputs": ["a.ao"]
})",
                               &plan);
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  EXPECT_TRUE(plan.has_value());
}

TEST(ParseMalformedGraphControl, ValidPathsInsideTheFolderCompile) {
  for (const char* path : {"assets/day.hdr", "assets/../assets/day.HDR", "./assets/day.hdr"}) {
    SCOPED_TRACE(path);
    TempDir dir;
    std::string text = load_path(path);
    std::string file = write_case_folder(dir, text);
    if (std::string(path).find("HDR") != std::string::npos)
      write_text((dir.path() / "graphs" / "assets" / "day.HDR").string(), "#?RADIANCE\n");
    Diagnostics d;
    auto graph = load_graph_file(file, d);
    ASSERT_TRUE(graph) << d.to_string();
    CompileResult result = compile(*graph, builtin_registry(), CompileOptions{}, d);
    EXPECT_TRUE(d.items().empty()) << d.to_string();
    EXPECT_TRUE(result.plan.has_value());
  }
}

TEST(ParseMalformedGraphControl, AnExtraAssetRootAllowsAPathOutsideTheFolder) {
  TempDir dir;
  std::string file = write_case_folder(dir, load_path("../outside/sky.hdr"));
  Diagnostics d;
  auto graph = load_graph_file(file, d);
  ASSERT_TRUE(graph) << d.to_string();
  CompileOptions options;
  options.roots.roots = {(dir.path() / "outside").string()};
  CompileResult result = compile(*graph, builtin_registry(), options, d);
  EXPECT_TRUE(d.items().empty()) << d.to_string();
  EXPECT_TRUE(result.plan.has_value());
}

// --- Every error, not only the first ------------------------------------------------------------

std::vector<std::string> located(const Diagnostics& d) {
  std::vector<std::string> out;
  for (const auto& item : d.items()) out.push_back(item.to_string());
  return out;
}

TEST(ParseMalformedGraphAll, EveryIndependentCompileErrorIsReported) {
  Diagnostics d = compile_text(R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbufer" },
    { "id": "l", "type": "lighting.deferred", "params": { "shadow_map_size": 10 } },
    { "id": "s", "type": "env.sky" },
    { "id": "t", "type": "post.tonemap", "params": { "curve": "filmic" } }
  ],
  "links": [
    { "from": "s.cube", "to": "t.color" },
    { "from": "t.color", "to": "x.color" }
  ],
  "outputs": ["t.colour"]
})");
  d.sort_by_position();
  // Exactly these: one per mistake, none lost, and no knock-on errors from the unknown type.
  EXPECT_EQ(located(d), (std::vector<std::string>{
                            "<graph>:4:26: error: unknown node type 'scene.gbufer'; did you mean 'scene.gbuffer'? (/nodes/0/type)",
                            "<graph>:5:5: error: node 'l' (lighting.deferred) needs its input 'gbuffer' (gbuffer) linked (/nodes/1)",
                            "<graph>:5:78: error: param 'shadow_map_size' of node 'l' (lighting.deferred) must be an integer "
                            "from 64 to 8192 (texels) (/nodes/1/params/shadow_map_size)",
                            "<graph>:7:63: error: param 'curve' of node 't' (post.tonemap) must be one of \"aces_fitted\", "
                            "\"neutral\", \"clamp\" (/nodes/3/params/curve)",
                            "<graph>:10:31: error: cannot link s.cube (cube:hdr) to t.color (texture2d:hdr): a cube map cannot "
                            "feed a 2D texture (/links/0/to)",
                            "<graph>:11:32: error: no node with id 'x' (/links/1/to)",
                            "<graph>:13:15: error: node 't' (post.tonemap) has no output 'colour'; did you mean 'color'? (/outputs/0)",
                        }));
}

TEST(ParseMalformedGraphAll, EveryIndependentStructuralErrorIsReported) {
  Diagnostics d = compile_text(R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "a b", "type": "post.tonemap" },
    { "type": "post.bloom" },
    { "id": "c", "type": 5 }
  ],
  "links": [ { "from": "a.b.c", "to": "c.color" } ],
  "outputs": ["c"],
  "extra": true
})");
  d.sort_by_position();
  EXPECT_EQ(located(d), (std::vector<std::string>{
                            "<graph>:4:13: error: invalid node id 'a b': use 1 to 64 letters, digits, '_' or '-' (/nodes/0/id)",
                            "<graph>:5:5: error: node has no \"id\" (/nodes/1)",
                            "<graph>:6:26: error: expected a string, found a number (/nodes/2/type)",
                            "<graph>:8:24: error: expected \"node.port\" (for example \"sky.cube\"), found \"a.b.c\" (/links/0/from)",
                            "<graph>:9:15: error: expected \"node.port\" (for example \"sky.cube\"), found \"c\" (/outputs/0)",
                            "<graph>:10:12: error: unknown key 'extra'; expected format, name, nodes, links, outputs, editor (/extra)",
                        }));
}

TEST(ParseMalformedGraphAll, AnUnresolvedOutputCausesNoKnockOnErrors) {
  // The graph does ask for something; the misspelt output or unknown type says what. A second
  // error claiming "the graph asks for nothing" would send the reader the wrong way.
  for (const std::string& text :
       {base_with(12, R"(  "outputs": ["t.colour"])"),
        std::string(R"({"format": "lumagraph/1", "nodes": [{"id": "o", "type": "output.dispaly"}]})")}) {
    Diagnostics d = compile_text(text);
    EXPECT_EQ(d.items().size(), 1u) << d.to_string();
  }
}

TEST(ParseMalformedGraphAll, ManyBadReferencesAreAllReported) {
  // 20,000 nodes and 20,000 links to unknown nodes: every link is reported. The "did you mean"
  // search over all ids is bounded (it once took over 30 s here; no test asserts time).
  std::string text = "{\"format\": \"lumagraph/1\", \"nodes\": [";
  for (int k = 0; k < 20000; ++k) text += (k ? "," : "") + std::string("{\"id\": \"n") + std::to_string(k) + "\", \"type\": \"scene.gbuffer\"}";
  text += "], \"links\": [";
  for (int k = 0; k < 20000; ++k)
    text += (k ? "," : "") + std::string("{\"from\": \"x") + std::to_string(k) + ".gbuffer\", \"to\": \"n0.gbuffer\"}";
  text += "], \"outputs\": [\"n0.gbuffer\"]}";
  Diagnostics d = compile_text(text);
  size_t unknown = 0;
  for (const auto& item : d.items()) unknown += item.message.rfind("no node with id 'x", 0) == 0;
  EXPECT_EQ(unknown, 20000u);
}

}  // namespace
}  // namespace lg
