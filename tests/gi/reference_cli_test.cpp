// `lumagraph reference` run as a process: bands of rows merged equal to a single run pixel for
// pixel (EXR files carry their creation time, so their pixels are compared), the standard-error
// image beside the result, and bad input ending in the documented exit status with a message
// that says what is wrong.
#include <gtest/gtest.h>

#include <filesystem>

#include "runtime/image/image_file.h"
#include "tests/parse/cli_runner.h"

namespace lg {
namespace {

using parse_test::contains;
using parse_test::lumagraph;
using parse_test::Outcome;
using parse_test::TempDir;
using parse_test::write_text;

const std::vector<std::string> kSmall = {"examples/worlds/cornell-box.json", "--size", "24x16", "--spp", "4"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

TEST(ReferenceCli, ChunksMergeToTheSingleRunPixelForPixel) {
  TempDir dir;
  std::vector<std::string> whole{"reference"};
  Outcome r = lumagraph(with(with(whole, kSmall), {"--aov", "indirect_diffuse", "--out", dir.file("whole.exr")}));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "wrote " + dir.file("whole.stderr.exr")));
  std::vector<std::string> merge{"reference", "merge"};
  for (int i = 2; i >= 0; --i) {  // parts in reverse order: merge sorts them
    const std::string part = dir.file("part" + std::to_string(i) + ".lgref");
    r = lumagraph(with(with({"reference"}, kSmall), {"--chunk", std::to_string(i) + "/3", "--out", part}));
    ASSERT_EQ(r.status, 0) << r.err;
    merge.push_back(part);
  }
  r = lumagraph(with(merge, {"--aov", "indirect_diffuse", "--out", dir.file("merged.exr")}));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {".exr", ".stderr.exr"}) {
    const ImageData a = load_image(dir.file(std::string("merged") + name));
    const ImageData b = load_image(dir.file(std::string("whole") + name));
    EXPECT_EQ(a.width, 24u);
    EXPECT_EQ(a.rgba, b.rgba) << name;
  }
  double sum = 0.0;  // the indirect light of the box is there, not zeros
  for (float v : load_image(dir.file("whole.exr")).rgba) sum += v;
  EXPECT_GT(sum, 24.0 * 16.0);  // the alpha channel alone gives 384
}

TEST(ReferenceCli, BadInputSaysWhatIsWrong) {
  TempDir dir;
  const std::string out = dir.file("x.exr");
  Outcome r = lumagraph({"reference", "--out", out, "--spp", "0"});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--spp expects a count from 1 to 1048576; got '0'")) << r.err;
  r = lumagraph({"reference", "--out", out, "--aov", "albedo"});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--aov expects radiance, emission, direct, indirect_diffuse or specular")) << r.err;
  r = lumagraph({"reference", "--out", out, "--chunk", "3/3"});
  EXPECT_EQ(r.status, 1);
  r = lumagraph({"reference"});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--out FILE is required")) << r.err;
  r = lumagraph({"reference", dir.file("missing.json"), "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "missing.json")) << r.err;
  write_text(dir.file("broken.json"), R"({ "format": "lumagraph/1", "nodes": [ { "id": "s", "type": "env.skyy" } ] })");
  r = lumagraph({"reference", "--graph", dir.file("broken.json"), "--size", "8x8", "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "broken.json:1:")) << r.err;
  write_text(dir.file("part.lgref"), "lumagraph-reference/1\nchunk 0 2 width 8 height 8 rows 0 4 non_finite 0\nrun\n");
  r = lumagraph({"reference", "merge", dir.file("part.lgref"), "--out", out});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "part.lgref: error: truncated")) << r.err;
}

}  // namespace
}  // namespace lg
