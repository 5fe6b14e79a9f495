// `lumagraph bake` run as a process: chunked bakes merged byte for byte equal to a single run
// (vertex on the bunny, volume and texel on a small OBJ, side files included), and bad input —
// a missing or NaN mesh, an empty mesh, bad options, parts that do not fit — ending in the
// documented exit status with a message that names the file. And the occlusion.bake graph node:
// it compiles and renders per frame through `lumagraph render`.
#include <gtest/gtest.h>

#include <filesystem>

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

// A unit cube on a floor, as OBJ (counter-clockwise seen from outside).
const char* cube_on_floor_obj = R"(v -2 0 -2
v 2 0 -2
v 2 0 2
v -2 0 2
v 0 0 0
v 1 0 0
v 1 0 1
v 0 0 1
v 0 1 0
v 1 1 0
v 1 1 1
v 0 1 1
f 1 4 3
f 1 3 2
f 5 6 7
f 5 7 8
f 9 12 11
f 9 11 10
f 5 9 10
f 5 10 6
f 6 10 11
f 6 11 7
f 7 11 12
f 7 12 8
f 8 12 9
f 8 9 5
)";

// Bakes `input` whole and in `chunks` parts, merges the parts, and expects every file the whole
// bake wrote (the .lgbake and its side files) byte-identical in the merge; EXR files carry their
// creation time, so of those the pixels must be identical.
void expect_merge_matches_single_run(const std::string& input, std::vector<std::string> options, int chunks,
                                     const std::vector<std::string>& side_files) {
  TempDir dir;
  std::vector<std::string> whole{"bake", input, "--out", dir.file("whole.lgbake")};
  whole.insert(whole.end(), options.begin(), options.end());
  Outcome r = lumagraph(whole);
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> merge{"bake", "merge"};
  for (int i = chunks - 1; i >= 0; --i) {  // parts in reverse order: merge sorts them
    const std::string part = dir.file("part" + std::to_string(i) + ".lgbake");
    std::vector<std::string> bake{"bake",  input, "--chunk", std::to_string(i) + "/" + std::to_string(chunks),
                                  "--out", part};
    bake.insert(bake.end(), options.begin(), options.end());
    r = lumagraph(bake);
    ASSERT_EQ(r.status, 0) << r.err;
    merge.push_back(part);
  }
  merge.insert(merge.end(), {"--out", dir.file("merged.lgbake")});
  r = lumagraph(merge);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_text(dir.file("merged.lgbake")), read_text(dir.file("whole.lgbake")));
  for (const std::string& ext : side_files) {
    ASSERT_TRUE(fs::exists(dir.file("whole" + ext))) << ext;
    if (ext == ".exr") {
      EXPECT_EQ(load_image(dir.file("merged" + ext)).rgba, load_image(dir.file("whole" + ext)).rgba);
    } else {
      EXPECT_EQ(read_text(dir.file("merged" + ext)), read_text(dir.file("whole" + ext))) << ext;
    }
  }
}

TEST(BakeCli, BunnyVertexChunksMergeToTheSingleRunByteForByte) {
  const std::string bunny = "../shared/data/mesh/bunny.obj";
  if (!fs::exists(bunny)) GTEST_SKIP() << bunny << " is not here";
  expect_merge_matches_single_run(bunny, {"--rays", "32"}, 3, {});
}

TEST(BakeCli, VolumeAndTexelChunksMergeToTheSingleRunByteForByte) {
  TempDir dir;
  write_text(dir.file("cube.obj"), cube_on_floor_obj);
  expect_merge_matches_single_run(dir.file("cube.obj"), {"--mode", "volume", "--resolution", "8", "--rays", "16"}, 3,
                                  {".vti"});
  expect_merge_matches_single_run(
      dir.file("cube.obj"),
      {"--mode", "texel", "--resolution", "32", "--rays", "16", "--max-distance", "0.5", "--falloff", "obscurance"}, 3,
      {".png", ".exr"});
}

TEST(BakeCli, TexelBakeWritesItsImages) {
  TempDir dir;
  write_text(dir.file("cube.obj"), cube_on_floor_obj);
  Outcome r = lumagraph({"bake", dir.file("cube.obj"), "--mode", "texel", "--resolution", "48", "--rays", "16", "--out",
                         dir.file("cube.lgbake")});
  ASSERT_EQ(r.status, 0) << r.err;
  const ImageData ao = load_image(dir.file("cube.png"));
  EXPECT_EQ(ao.width, 48u);
  EXPECT_EQ(ao.height, 48u);
  const ImageData bent = load_image(dir.file("cube.exr"));
  EXPECT_EQ(bent.width, 48u);
  EXPECT_TRUE(contains(r.out, "wrote " + dir.file("cube.exr"))) << r.out;
}

TEST(BakeCli, BadInputEndsInItsExitStatusAndNamesTheFile) {
  TempDir dir;
  // A NaN position (glTF carries binary floats): the loader names the file and the primitive.
  write_text(dir.file("nan.gltf"),
             R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": )"
             R"("data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAwH8AAAAA"}], )"
             R"("bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors": [{"bufferView": 0, )"
             R"("componentType": 5126, "count": 3, "type": "VEC3"}], "meshes": [{"primitives": [{"attributes": )"
             R"({"POSITION": 0}}]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
  write_text(dir.file("empty.obj"), "# no triangles\n");
  write_text(dir.file("point.obj"), "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  write_text(dir.file("degenerate.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 1 1\nf 1 2 3\nf 4 4 4\nf 1 2 4\n");
  write_text(dir.file("junk.lgbake"), std::string("LGBAKE01\xff\xff\xff\xff\xff\xff\xff\x7f{}", 18));
  const std::string out = dir.file("out.lgbake");
  struct Case {
    std::vector<std::string> args;
    int status;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"bake", dir.file("missing.obj"), "--out", out}, 2, "missing.obj"},
      {{"bake", dir.file("nan.gltf"), "--out", out},
       2,
       "nan.gltf: error: mesh 0 primitive 0: a vertex position is not finite"},
      {{"bake", dir.file("empty.obj"), "--out", out}, 2, "empty.obj"},
      {{"bake", dir.file("point.obj"), "--mode", "volume", "--out", out},
       2,
       "point.obj: error: a volume bake needs geometry with extent"},
      {{"bake", dir.file("degenerate.obj"), "--mode", "texel", "--resolution", "4", "--out", out},
       2,
       "the size must be at least 8"},
      {{"bake", dir.file("degenerate.obj"), "--rays", "2000000", "--out", out},
       1,
       "--rays expects a count from 1 to 1048576"},
      {{"bake", dir.file("degenerate.obj"), "--chunk", "3/3", "--out", out}, 1, "--chunk expects I/N"},
      {{"bake", dir.file("degenerate.obj"), "--resolution", "8", "--out", out}, 1, "not vertex"},
      {{"bake", dir.file("degenerate.obj"), "--falloff", "obscurance", "--out", out}, 1, "needs --max-distance"},
      {{"bake", dir.file("degenerate.obj")}, 1, "--out PATH is required"},
      {{"bake", "merge", dir.file("junk.lgbake"), "--out", out}, 2, "junk.lgbake: the header length"},
  };
  for (const Case& c : cases) {
    Outcome r = lumagraph(c.args);
    EXPECT_EQ(r.status, c.status) << c.args[1] << " " << r.err;
    EXPECT_TRUE(contains(r.err, c.message)) << "expected '" << c.message << "' in:\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args[1];
  }
  // Degenerate triangles bake: the zero-area ones are never hit, and every vertex gets a value.
  Outcome r = lumagraph({"bake", dir.file("degenerate.obj"), "--rays", "16", "--out", out});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "baked 4 vertex points")) << r.out;
  r = lumagraph({"bake", "--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(contains(r.out, "lumagraph bake merge PART... --out PATH"));
}

TEST(BakeCli, TheGraphNodeCompilesAndRendersPerFrame) {
  TempDir dir;
  write_text(dir.file("bake.json"), R"({ "format": "lumagraph/1", "name": "bake-only",
    "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" },
               { "id": "bake", "type": "occlusion.bake", "params": { "resolution": 16, "rays": 16 } },
               { "id": "out", "type": "output.display" } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "bake.gbuffer" }, { "from": "bake.ao", "to": "out.color" } ],
    "outputs": [] })");
  Outcome r = lumagraph({"compile", dir.file("bake.json"), "--format", "text"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "bake/lookup")) << r.out;
  r = lumagraph({"render", dir.file("bake.json"), "--size", "8x8", "--out", dir.file("x.png")});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("x.png")));
}

}  // namespace
}  // namespace lg
