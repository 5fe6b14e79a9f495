// `lumagraph render` run as a process: it writes the image, the stats and the dump it is asked
// for with zero validation messages, and broken input — a corrupt or missing scene, a broken
// graph, bad options — ends in an exit status and a message that names the file, never a
// crash. (A node without a kernel is the executor's error; tests/runtime/exec_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "graph/json_reader.h"
#include "runtime/image/image_file.h"
#include "tests/parse/cli_runner.h"

namespace lg {
namespace {

namespace fs = std::filesystem;
using parse_test::contains;
using parse_test::lumagraph;
using parse_test::Outcome;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

TEST(RenderCli, WritesImageStatsAndDump) {
  TempDir dir;
  Outcome r = lumagraph({"render", "examples/minimal.json", "--size", "160x90", "--out", dir.file("frame.png"),
                         "--stats", dir.file("stats.json"), "--dump", dir.file("dump"), "--validate"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "light/area")) << "the per-pass GPU times are printed:\n" << r.out;
  ImageData image = load_image(dir.file("frame.png"));
  EXPECT_EQ(image.width, 160u);
  EXPECT_EQ(image.height, 90u);
  Diagnostics d;
  std::optional<JsonValue> stats = read_json(read_text(dir.file("stats.json")), d);
  ASSERT_TRUE(stats) << d.to_string();
  ASSERT_TRUE(stats->find("passes"));
  EXPECT_EQ(stats->find("passes")->size(), 5u);
  for (const char* port : {"gbuf.gbuffer.normal.exr", "gbuf.gbuffer.depth.exr", "light.color.exr", "tonemap.color.exr"})
    EXPECT_TRUE(fs::exists(dir.path() / "dump" / port)) << port;
}

TEST(RenderCli, CorruptSceneNamesTheFile) {
  TempDir dir;
  write_text(dir.file("broken.gltf"),
             "{ \"asset\": { \"version\": \"2.0\" }, \"meshes\": [ { \"primitives\": [ { \"attributes\": { "
             "\"POSITION\": 7 } } ] } ] ");
  write_text(dir.file("broken.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
  for (const char* name : {"broken.gltf", "broken.obj", "missing.json"}) {
    Outcome r = lumagraph({"render", "examples/minimal.json", "--scene", dir.file(name), "--out", dir.file("x.png")});
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_TRUE(contains(r.err, name)) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
  }
}

TEST(RenderCli, BrokenGraphGetsLocatedErrors) {
  TempDir dir;
  write_text(
      dir.file("g.json"),
      "{ \"format\": \"lumagraph/1\", \"nodes\": [ { \"id\": \"a\", \"type\": \"scene.gbufer\" } ], \"links\": [] }");
  Outcome r = lumagraph({"render", dir.file("g.json"), "--out", dir.file("x.png")});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "g.json:1:")) << r.err;
  EXPECT_TRUE(contains(r.err, "did you mean 'scene.gbuffer'")) << r.err;
}

// A scene whose mesh lies outside the scene's folder renders once --asset-root allows that folder,
// as the refusal's message says; the scene's own folder stays allowed beside it.
// A frame that fails on the device (an injected failure, graph/fault_injection.h): status 3, the
// pass named, no image written.
TEST(RenderCli, AFailedFrameExitsWithStatus3NamingThePass) {
  TempDir dir;
  Outcome r = lumagraph({"render", "examples/minimal.json", "--size", "64x36", "--out", dir.file("frame.png")},
                        "LUMAGRAPH_FAULT=shader_module:1");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_TRUE(contains(r.err, "pass '") && contains(r.err, "vkCreateShaderModule failed")) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("frame.png")));
}

TEST(RenderCli, AssetRootAllowsSceneFilePaths) {
  TempDir dir;
  fs::create_directories(dir.path() / "meshes");
  fs::create_directories(dir.path() / "scenes");
  write_text(dir.file("meshes/tri.obj"), "v -1 0 -1\nv 1 0 -1\nv 0 0 1\nf 1 3 2\n");
  write_text(dir.file("scenes/world.json"),
             "{ \"format\": \"lumagraph-world/1\", \"entities\": [ { \"name\": \"tri\", \"model\": "
             "\"../meshes/tri.obj\" } ] }");
  const std::vector<std::string> render = {
      "render", "examples/minimal.json", "--scene", dir.file("scenes/world.json"), "--size", "32x18",
      "--out",  dir.file("x.png")};
  Outcome refused = lumagraph(render);
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_TRUE(contains(refused.err, "world.json:1:")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "pass --asset-root")) << refused.err;

  std::vector<std::string> allowed = render;
  allowed.insert(allowed.end(), {"--asset-root", dir.file("meshes")});
  Outcome r = lumagraph(allowed);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("x.png")));
}

// The pipeline cache on disk ($XDG_CACHE_HOME/lumagraph): a corrupt file is ignored with one
// warning naming it and the image is the same; --no-pipeline-cache neither reads nor writes one.
TEST(RenderCli, ACorruptPipelineCacheFileIsIgnoredWithAWarning) {
  TempDir dir;
  const std::string cache_home = "XDG_CACHE_HOME=" + dir.file("cache");
  auto render = [&](const std::string& out, const std::string& option = "--validate") {
    return lumagraph({"render", "examples/minimal.json", "--size", "64x36", option, "--out", dir.file(out)},
                     cache_home);
  };
  Outcome first = render("first.png");
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_FALSE(contains(first.err, "warning")) << first.err;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir.path() / "cache" / "lumagraph")) files.push_back(entry.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].filename().string().rfind("pipeline-cache-", 0), 0u) << files[0];

  write_text(files[0].string(), "not a pipeline cache, but long enough to hold a header of one");
  Outcome second = render("second.png");
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_TRUE(contains(second.err, "warning: pipeline cache " + files[0].string() + " ignored: ")) << second.err;
  EXPECT_EQ(read_text(dir.file("second.png")), read_text(dir.file("first.png")));

  fs::remove_all(dir.path() / "cache");
  Outcome off = render("off.png", "--no-pipeline-cache");
  ASSERT_EQ(off.status, 0) << off.err;
  EXPECT_FALSE(fs::exists(dir.path() / "cache" / "lumagraph"));
}

// Static results on disk beside it: a warm run prints the static passes as cached and writes the
// same image; a corrupt results file is ignored with a warning naming it, and the image is the same.
TEST(RenderCli, StaticResultsAreReusedAndACorruptFileIsIgnoredWithAWarning) {
  TempDir dir;
  // The default graph with small cubes and a sampled prefilter: three cold-ish runs stay quick.
  std::string graph = read_text("examples/default.json");
  const std::pair<std::string, std::string> quick[] = {
      {"\"sun_intensity\": 20 }", "\"sun_intensity\": 20, \"face_size\": 32 }"},
      {"{ \"face_size\": 128, \"mips\": 6 }", "{ \"face_size\": 32, \"mips\": 4, \"method\": \"sampled\" }"}};
  for (const auto& [from, to] : quick) {
    ASSERT_NE(graph.find(from), std::string::npos) << from;
    graph.replace(graph.find(from), from.size(), to);
  }
  write_text(dir.file("quick.json"), graph);
  const std::string cache_home = "XDG_CACHE_HOME=" + dir.file("cache");
  auto render = [&](const std::string& out) {
    return lumagraph({"render", dir.file("quick.json"), "--size", "64x36", "--validate", "--out", dir.file(out)},
                     cache_home);
  };
  Outcome cold = render("cold.png");
  ASSERT_EQ(cold.status, 0) << cold.err;
  EXPECT_FALSE(contains(cold.out, "cached")) << cold.out;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir.path() / "cache" / "lumagraph"))
    if (entry.path().filename().string().starts_with("static-results-")) files.push_back(entry.path());
  ASSERT_EQ(files.size(), 1u);

  Outcome warm = render("warm.png");
  ASSERT_EQ(warm.status, 0) << warm.err;
  EXPECT_TRUE(contains(warm.out, "specular/prefilter          cached")) << warm.out;
  EXPECT_FALSE(contains(warm.err, "warning")) << warm.err;
  EXPECT_EQ(read_text(dir.file("warm.png")), read_text(dir.file("cold.png")));

  write_text(files[0].string(), "not static results, but long enough to hold a header of them........");
  Outcome corrupt = render("corrupt.png");
  ASSERT_EQ(corrupt.status, 0) << corrupt.err;
  EXPECT_TRUE(contains(corrupt.err, "warning: static results " + files[0].string() + " ignored")) << corrupt.err;
  EXPECT_FALSE(contains(corrupt.out, "cached")) << corrupt.out;
  EXPECT_EQ(read_text(dir.file("corrupt.png")), read_text(dir.file("cold.png")));
}

TEST(RenderCli, BadOptionsAreUsageErrors) {
  for (std::vector<std::string> args : {std::vector<std::string>{"render", "--frames", "0"},
                                        {"render", "--frame-seconds", "-1"},
                                        {"render", "--frame-seconds", "nan"},
                                        {"render", "--frame-seconds", "1e-60"},  // 0 as a float
                                        {"render", "--frame-seconds", "0.5s"},
                                        {"render", "--size", "12x"},
                                        {"render", "--colour"},
                                        {"render", "a.json", "b.json"}}) {
    Outcome r = lumagraph(args);
    EXPECT_EQ(r.status, 1) << args[1] << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "lumagraph render:")) << r.err;
    if (args[1] == "--frame-seconds") {
      EXPECT_TRUE(contains(r.err, "--frame-seconds expects a time in seconds above 0") &&
                  contains(r.err, "got '" + args[2] + "'"))
          << r.err;
    }
  }
}

// --frame-seconds is the step post.exposure adapts by. Exposure node 'a' reads node 'b''s last
// exposure as its history; 'b' meters 5 EV brighter ('compensation'), so on the second frame
// 'a' falls from b's value towards its own at speed_down (3 EV/s) for one frame time:
// b - a = 3 x 0.25 s. The dump holds the two values as half floats: each within 2^-11 of itself.
TEST(RenderCli, FrameSecondsIsTheTimeExposureAdaptsOver) {
  TempDir dir;
  write_text(dir.file("g.json"), R"({ "format": "lumagraph/1", "nodes": [
    { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "light", "type": "lighting.deferred" },
    { "id": "a", "type": "post.exposure" },
    { "id": "b", "type": "post.exposure", "params": { "compensation": 5 } },
    { "id": "tonemap", "type": "post.tonemap" }, { "id": "out", "type": "output.display" } ],
  "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" }, { "from": "light.color", "to": "a.color" },
    { "from": "light.color", "to": "b.color" }, { "from": "b.exposure", "to": "a.history" },
    { "from": "b.exposure", "to": "b.history" }, { "from": "light.color", "to": "tonemap.color" },
    { "from": "a.exposure", "to": "tonemap.auto_exposure" }, { "from": "tonemap.color", "to": "out.color" } ],
  "outputs": ["b.exposure"] })");
  Outcome r = lumagraph({"render", dir.file("g.json"), "--size", "32x18", "--frames", "2", "--frame-seconds", "0.25",
                         "--out", dir.file("x.png"), "--dump", dir.file("dump")});
  ASSERT_EQ(r.status, 0) << r.err;
  const double a = load_image(dir.file("dump/a.exposure.exr")).rgba.at(0);
  const double b = load_image(dir.file("dump/b.exposure.exr")).rgba.at(0);
  EXPECT_NEAR(b - a, 0.75, (std::abs(a) + std::abs(b)) * std::exp2(-11)) << "a " << a << ", b " << b;
}

}  // namespace
}  // namespace lg
