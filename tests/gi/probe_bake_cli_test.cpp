// `lumagraph bake --mode probes` run as a process on the two rooms (128 probes, few rays): a bake
// split into chunks and merged is byte-identical to a single run, its .vti included; merge
// refuses parts of another run, a chunk missing or given twice; a scene without volumes and
// options of the other bakes end in the documented exit status with a message naming the problem.
#include <gtest/gtest.h>

#include "tests/parse/cli_runner.h"

namespace lg {
namespace {

using parse_test::contains;
using parse_test::lumagraph;
using parse_test::Outcome;
using parse_test::read_text;
using parse_test::TempDir;
using parse_test::write_text;

const std::string kRooms = "examples/worlds/two-rooms.json";

std::vector<std::string> bake(const std::string& out, std::vector<std::string> more = {}) {
  std::vector<std::string> args{"bake", kRooms, "--mode", "probes", "--rays", "16", "--bounces", "1", "--out", out};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(ProbeBakeCli, ChunksMergeByteIdenticalToASingleRun) {
  TempDir dir;
  Outcome r = lumagraph(bake(dir.file("whole.lgprobes")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "baked 128 probes of " + kRooms)) << r.out;
  EXPECT_TRUE(contains(r.out, "wrote " + dir.file("whole.vti"))) << r.out;
  std::vector<std::string> merge{"bake", "merge"};
  for (int i = 2; i >= 0; --i) {  // parts in reverse order: merge sorts them
    const std::string part = dir.file("part" + std::to_string(i) + ".lgprobes");
    r = lumagraph(bake(part, {"--chunk", std::to_string(i) + "/3"}));
    ASSERT_EQ(r.status, 0) << r.err;
    merge.push_back(part);
  }
  std::vector<std::string> args = merge;
  args.insert(args.end(), {"--out", dir.file("merged.lgprobes")});
  r = lumagraph(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "merged 3 parts: 128 probes")) << r.out;
  // Every probe's 549 floats in the bake, 10 in the .vti.
  for (auto [name, floats] : {std::pair{".lgprobes", 549u}, std::pair{".vti", 10u}}) {
    const std::string whole = read_text(dir.file(std::string("whole") + name));
    EXPECT_GT(whole.size(), 128u * floats * 4u) << name;
    EXPECT_TRUE(whole == read_text(dir.file(std::string("merged") + name))) << name;
  }

  // A chunk missing, a chunk twice, a part of another run (another seed); merge[2..4] are parts 2, 1, 0.
  args = {"bake", "merge", merge[2], merge[3], "--out", dir.file("bad.lgprobes")};
  r = lumagraph(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "merge: chunks missing of 3: 0")) << r.err;
  args = {"bake", "merge", merge[2], merge[3], merge[4], merge[4], "--out", dir.file("bad.lgprobes")};
  r = lumagraph(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, merge[4] + ": chunk 0 is also in " + merge[4])) << r.err;
  r = lumagraph(bake(dir.file("seed2.lgprobes"), {"--chunk", "1/3", "--seed", "2"}));
  ASSERT_EQ(r.status, 0) << r.err;
  args = {"bake", "merge", merge[2], dir.file("seed2.lgprobes"), merge[4], "--out", dir.file("bad.lgprobes")};
  r = lumagraph(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, dir.file("seed2.lgprobes") + ": belongs to another probe bake than " + merge[2]))
      << r.err;
  // A damaged part is named.
  const std::string part1 = read_text(merge[3]);
  write_text(dir.file("cut.lgprobes"), part1.substr(0, part1.size() - 100));
  args = {"bake", "merge", merge[2], dir.file("cut.lgprobes"), merge[4], "--out", dir.file("bad.lgprobes")};
  r = lumagraph(args);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, dir.file("cut.lgprobes") + ": the file has " + std::to_string(part1.size() - 100) +
                                  " bytes; its header describes " + std::to_string(part1.size()) +
                                  " (truncated or damaged)"))
      << r.err;
}

TEST(ProbeBakeCli, ASceneWithoutVolumesAndWrongOptionsAreRefused) {
  TempDir dir;
  write_text(dir.file("box.json"), R"({"format": "lumagraph-world/1", "entities": [
    {"name": "box", "shape": {"type": "box", "size": [1, 1, 1]}}]})");
  Outcome r = lumagraph({"bake", dir.file("box.json"), "--mode", "probes", "--out", dir.file("x.lgprobes")});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, dir.file("box.json") + ": error: the scene has no irradiance volume to bake")) << r.err;
  r = lumagraph(bake(dir.file("x.lgprobes"), {"--resolution", "8"}));
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--resolution applies to occlusion bakes, not --mode probes")) << r.err;
  r = lumagraph({"bake", kRooms, "--mode", "probes", "--bounces", "0", "--out", dir.file("x.lgprobes")});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--bounces expects a count from 1 to 1024; got '0'")) << r.err;
  r = lumagraph({"bake", kRooms, "--bounces", "2", "--out", dir.file("x.lgbake")});
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "--bounces applies to --mode probes only")) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.lgprobes")));
}

}  // namespace
}  // namespace lg
