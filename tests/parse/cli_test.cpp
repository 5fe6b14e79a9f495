// The `lumagraph` command, run as a process the way users and scripts run it: exit statuses
// (0 done, 1 usage error, 2 invalid input), errors on stderr as path:line:col: error:, and
// machine-readable output that really is valid JSON.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "graph/json_reader.h"
#include "tests/parse/cli_runner.h"
#include "tests/parse/parse_test_support.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::lumagraph;
using parse_test::Outcome;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

std::optional<JsonValue> json_of(const std::string& text, std::string* errors) {
  Diagnostics d;
  auto v = read_json(text, d);
  *errors = d.to_string();
  return v;
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

TEST(ParseCli, TheBinaryExists) {
  // Every other test here would fail confusingly without it.
  ASSERT_TRUE(fs::exists(LUMAGRAPH_BINARY_DIR "/lumagraph"));
  ASSERT_TRUE(fs::exists("examples/post.json")) << "tests must run from the source root";
}

// The version is the project's (CMakeLists.txt), so a package's binaries say which they are.
TEST(ParseCli, VersionPrintsTheProjectVersion) {
  Outcome r = lumagraph({"--version"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "lumagraph " LUMAGRAPH_VERSION "\n");
}

TEST(ParseCli, CompileWithNoArgumentsPrintsThePlanOfTheEmbeddedDefault) {
  Outcome r = lumagraph({"compile"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(starts_with(r.out, "plan 'deferred-ibl', scene 'default', frame 1280x720\n")) << r.out;
  EXPECT_NE(r.out.find("pass"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(ParseCli, CompileJsonIsValidJsonThatDescribesThePlan) {
  Outcome r = lumagraph({"compile", "examples/post.json", "--format", "json"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string errors;
  auto plan = json_of(r.out, &errors);
  ASSERT_TRUE(plan) << errors;
  ASSERT_TRUE(plan->is_object());
  ASSERT_NE(plan->find("format"), nullptr);
  EXPECT_EQ(plan->find("format")->as_string(), "lumagraph-plan/1");
  EXPECT_EQ(plan->find("name")->as_string(), "post-processing");
  ASSERT_NE(plan->find("passes"), nullptr);
  EXPECT_GT(plan->find("passes")->size(), 0u);
}

TEST(ParseCli, CompileDotIsAGraphvizDigraph) {
  Outcome r = lumagraph({"compile", "examples/post.json", "--format=dot"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(starts_with(r.out, "digraph")) << r.out.substr(0, 200);
  EXPECT_EQ(r.out.substr(r.out.size() - 2), "}\n");
}

TEST(ParseCli, ValidateReportsEachErrorAsPathLineColumnAndExits2) {
  TempDir dir;
  std::string path = dir.file("broken.json");
  write_text(path, R"({
  "format": "lumagraph/1",
  "nodes": [
    { "id": "g", "type": "scene.gbuffer" },
    { "id": "l", "type": "lighting.deferred" },
    { "id": "t", "type": "post.tonemap", "params": { "exposure": 99 } }
  ],
  "links": [
    { "from": "g.gbuffer", "to": "l.gbuffer" },
    { "from": "l.color", "to": "t.color" }
  ],
  "outputs": ["t.colour"]
}
)");
  Outcome r = lumagraph({"validate", path});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err,
            path +
                ":6:66: error: param 'exposure' of node 't' (post.tonemap) must be a number from -20 to 20 (EV) "
                "(/nodes/2/params/exposure)\n" +
                path +
                ":12:15: error: node 't' (post.tonemap) has no output 'colour'; did you mean 'color'? (/outputs/0)\n" +
                path + ": invalid (2 errors)\n");
}

TEST(ParseCli, ValidateReportsASyntaxErrorWithItsPlace) {
  TempDir dir;
  std::string path = dir.file("truncated.json");
  write_text(path, "{\n  \"format\": \"lumagraph/1\",\n  \"nodes\": [");
  Outcome r = lumagraph({"validate", path});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(starts_with(r.err, path + ":3:13: error: unexpected end of the file; expected a value\n")) << r.err;
}

TEST(ParseCli, ValidateAcceptsAValidGraph) {
  Outcome r = lumagraph({"validate", "examples/minimal.json"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(starts_with(r.out, "examples/minimal.json: valid (4 nodes, 3 links, ")) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(ParseCli, ValidateAMissingFileExits2AndNamesIt) {
  TempDir dir;
  Outcome r = lumagraph({"validate", dir.file("absent.json")});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(
      starts_with(r.err, dir.file("absent.json") + ": error: cannot open the file: No such file or directory\n"))
      << r.err;
}

TEST(ParseCli, CompileAnInvalidGraphExits2AndCountsTheErrors) {
  TempDir dir;
  std::string path = dir.file("g.json");
  write_text(path, "{\"format\": \"lumagraph/1\", \"nodes\": [{\"id\": \"t\", \"type\": \"post.tonemapp\"}]}");
  Outcome r = lumagraph({"compile", path});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(path + ":1:57: error: unknown node type 'post.tonemapp'; did you mean 'post.tonemap'?"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("lumagraph compile: 1 error\n"), std::string::npos) << r.err;
}

TEST(ParseCli, ABrokenSceneSummaryExits2WithItsErrors) {
  TempDir dir;
  std::string scene = dir.file("scene.json");
  write_text(scene, "{\n  \"format\": \"lumagraph-scene-summary/1\",\n  \"lights\": { \"point\": -2 }\n}\n");
  Outcome r = lumagraph({"compile", "--scene", scene});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(scene + ":3:24: error: expected a whole number from 0 to 1000000 (/lights/point)"),
            std::string::npos)
      << r.err;
}

TEST(ParseCli, UnknownOptionsAreUsageErrors) {
  for (const char* command : {"compile", "validate", "nodes"}) {
    SCOPED_TRACE(command);
    Outcome r = lumagraph({command, "--bogus"});
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(starts_with(r.err, std::string("lumagraph ") + command + ": unknown option '--bogus'\n")) << r.err;
    EXPECT_EQ(r.out, "");
  }
  Outcome single_dash = lumagraph({"compile", "-x"});
  EXPECT_EQ(single_dash.status, 1);
  EXPECT_TRUE(starts_with(single_dash.err, "lumagraph compile: unknown option '-x'\n")) << single_dash.err;
}

TEST(ParseCli, AnOptionIsNotTakenAsTheValueOfTheOptionBeforeIt) {
  Outcome r = lumagraph({"render", "--stats", "--output", "x.png"});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(starts_with(r.err, "lumagraph render: '--stats' needs a value, not the option '--output' (write "
                                 "--stats=--output if that is the value)\n"))
      << r.err;
  // The control: the same words with `=` are a value (here an unknown graph, so the option parsed).
  Outcome control = lumagraph({"compile", "--scene=--nothing"});
  EXPECT_EQ(control.status, 2) << control.err;
}

TEST(ParseCli, BadFrameSizesAreUsageErrors) {
  for (const char* size : {"0x720", "1280", "1280x", "1280x720x2", "abc", "16385x16", "-5x10", "1280x720junk"}) {
    SCOPED_TRACE(size);
    Outcome r = lumagraph({"compile", "--size", size});
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("--size expects WIDTHxHEIGHT, each from 1 to 16384"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  // The control: a good size is taken.
  Outcome r = lumagraph({"compile", "--size", "16384x1"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(starts_with(r.out, "plan 'deferred-ibl', scene 'default', frame 16384x1\n")) << r.out.substr(0, 200);
}

TEST(ParseCli, OtherUsageErrorsExit1) {
  EXPECT_EQ(lumagraph({}).status, 1);
  EXPECT_EQ(lumagraph({"render-everything"}).status, 1);
  EXPECT_EQ(lumagraph({"validate"}).status, 1);
  EXPECT_EQ(lumagraph({"validate", "a.json", "b.json"}).status, 1);
  EXPECT_EQ(lumagraph({"compile", "--format", "svg"}).status, 1);
  EXPECT_EQ(lumagraph({"compile", "--scene"}).status, 1);
  EXPECT_EQ(lumagraph({"compile", "--size", "1x1", "--size", "2x2"}).status, 1);
  EXPECT_EQ(lumagraph({"nodes", "extra"}).status, 1);
}

TEST(ParseCli, NodesJsonListsEveryNodeFolder) {
  // The types in the schemas under nodes/ ...
  std::set<std::string> expected;
  for (const auto& e : fs::recursive_directory_iterator("nodes"))
    if (e.path().filename() == "schema.json") {
      std::string errors;
      auto schema = json_of(read_text(e.path().string()), &errors);
      ASSERT_TRUE(schema) << e.path() << errors;
      expected.insert(schema->find("type")->as_string());
    }
  ASSERT_GE(expected.size(), 15u);

  // ... are exactly the types `nodes --json` lists.
  Outcome r = lumagraph({"nodes", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string errors;
  auto root = json_of(r.out, &errors);
  ASSERT_TRUE(root) << errors;
  EXPECT_EQ(root->find("format")->as_string(), "lumagraph-nodes/1");
  std::set<std::string> listed;
  for (const auto& node : root->find("nodes")->items()) listed.insert(node.find("type")->as_string());
  EXPECT_EQ(listed, expected);
  EXPECT_EQ(root->find("nodes")->size(), expected.size());  // and each once
}

TEST(ParseCli, HelpOnEachCommandExits0) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--help"}, {"compile", "--help"}, {"validate", "--help"}, {"nodes", "--help"}}) {
    SCOPED_TRACE(args.front());
    Outcome r = lumagraph(args);
    EXPECT_EQ(r.status, 0) << r.err;
    std::string usage = args.size() == 1 ? "usage: lumagraph COMMAND" : "usage: lumagraph " + args.front();
    EXPECT_TRUE(starts_with(r.out, usage)) << r.out;
    EXPECT_EQ(r.err, "");
  }
}

}  // namespace
}  // namespace lg
