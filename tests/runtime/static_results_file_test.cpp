// The static results file (runtime/exec/static_results_file.h) without a device: what it encodes
// decodes to the same results; every way a file goes wrong (cut short at any length, any byte
// flipped, made on another device or for another key) is refused with its reason; and the key
// changes with each thing that changes the results' bytes, the input files' contents hashed
// again only when a file's size or modification time changes.
#include "runtime/exec/static_results_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include "graph/fnv1a.h"
#include "runtime/exec/static_results_store.h"
#include "tests/runtime/test_device_identity.h"

namespace lg {
namespace {

using test::test_device;

std::vector<StoredResult> test_results() {
  std::mt19937 random(11);
  std::vector<StoredResult> results{{"sky.cube", std::vector<std::byte>(3000)}, {"sh.sh", std::vector<std::byte>(112)}};
  for (StoredResult& r : results)
    for (std::byte& b : r.bytes) b = std::byte(random());
  return results;
}

// Two static passes and the cached resources they write, as the compiler places them.
Plan static_plan() {
  Plan plan;
  plan.passes.push_back({.name = "sky/render", .pass = "render", .cache_key = 0x1111, .node = 0, .is_static = true});
  plan.passes.push_back({.name = "sh/project", .pass = "project", .cache_key = 0x2222, .node = 1, .is_static = true});
  plan.passes.push_back({.name = "tonemap/apply", .pass = "apply", .node = 2});
  PlanResource cube;
  cube.desc.name = "sky.cube", cube.desc.format = "rgba16f", cube.desc.kind = ResourceKind::cube;
  cube.desc.width = cube.desc.height = 64, cube.desc.layers = 6, cube.desc.mips = 7, cube.desc.bytes = 262136;
  cube.desc.lifetime = ResourceLifetime::cached;
  cube.placement.block = 1;
  plan.resources.push_back(cube);
  PlanResource color;
  color.desc.name = "tonemap.color", color.desc.format = "rgba8";
  color.placement.block = 0;
  plan.resources.push_back(color);
  return plan;
}

bool same(const std::vector<StoredResult>& a, const std::vector<StoredResult>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].bytes != b[i].bytes) return false;
  return true;
}

TEST(StaticResultsFile, RoundTripsTheResults) {
  const std::string file = encode_static_results(test_device(), 42, test_results());
  const DecodedStaticResults decoded = decode_static_results(file, test_device(), 42);
  EXPECT_EQ(decoded.problem, "");
  EXPECT_TRUE(same(decoded.results, test_results()));
}

TEST(StaticResultsFile, RefusesEveryTruncationAndEveryFlippedByte) {
  const std::string file = encode_static_results(test_device(), 42, test_results());
  for (size_t size = 0; size < file.size(); ++size) {
    const DecodedStaticResults decoded = decode_static_results(file.substr(0, size), test_device(), 42);
    ASSERT_TRUE(decoded.results.empty()) << size;
    ASSERT_NE(decoded.problem.find("truncated"), std::string::npos) << size << ": " << decoded.problem;
  }
  for (size_t at = 0; at < file.size(); ++at) {
    std::string flipped = file;
    flipped[at] = char(flipped[at] ^ 0x10);
    const DecodedStaticResults decoded = decode_static_results(flipped, test_device(), 42);
    ASSERT_TRUE(decoded.results.empty()) << at;
    ASSERT_FALSE(decoded.problem.empty()) << at;
  }
}

TEST(StaticResultsFile, RefusesAnotherDeviceOrKey) {
  DeviceIdentity newer = test_device();
  newer.driver_version += 1;
  const std::string file = encode_static_results(test_device(), 42, test_results());
  EXPECT_NE(decode_static_results(file, newer, 42).problem.find("another device or driver"), std::string::npos);
  EXPECT_NE(decode_static_results(file, test_device(), 43).problem.find("another key"), std::string::npos);
  EXPECT_NE(decode_static_results(std::string(4096, 'x'), test_device(), 42).problem.find("wrong magic"),
            std::string::npos);
}

TEST(StaticResultsFile, TheKeyChangesWithEverythingThatChangesTheBytes) {
  const StaticResultsIdentity identity{test_device(), 7, 9};
  const uint64_t key = static_results_key(static_plan(), identity);
  EXPECT_NE(key, 0u);
  EXPECT_EQ(static_results_key(static_plan(), identity), key) << "the same inputs, the same key";

  const std::pair<const char*, std::function<void(Plan&, StaticResultsIdentity&)>> changes[] = {
      {"a pass's cache key (a param)", [](Plan& p, StaticResultsIdentity&) { p.passes[1].cache_key ^= 1; }},
      {"the format", [](Plan& p, StaticResultsIdentity&) { p.resources[0].desc.format = "rgba32f"; }},
      {"the extent", [](Plan& p, StaticResultsIdentity&) { p.resources[0].desc.width = 128; }},
      {"the mips", [](Plan& p, StaticResultsIdentity&) { p.resources[0].desc.mips = 6; }},
      {"the driver", [](Plan&, StaticResultsIdentity& i) { i.device.driver_version ^= 1; }},
      {"the shaders", [](Plan&, StaticResultsIdentity& i) { i.code ^= 1; }},
      {"an input file", [](Plan&, StaticResultsIdentity& i) { i.inputs ^= 1; }},
  };
  for (const auto& [what, change] : changes) {
    Plan plan = static_plan();
    StaticResultsIdentity changed = identity;
    change(plan, changed);
    EXPECT_NE(static_results_key(plan, changed), key) << what;
  }
  Plan other = static_plan();
  other.resources[1].desc.width = 4096;  // not a static result: its shape is not the results'
  EXPECT_EQ(static_results_key(other, identity), key);
}

TEST(StaticResultsFile, APlanWithoutStaticPassesHasNothingToKeep) {
  Plan plan = static_plan();
  for (PlanPass& p : plan.passes) p.is_static = false;
  EXPECT_EQ(static_results_key(plan, {test_device(), 7, 9}), 0u);
}

// The editor compiles on every param edit: an input file is read and hashed once a process while
// it keeps its size and modification time. A rewrite that keeps both still gives the first key
// (so the file was not read again: the memo answered); a new time or size reads it again.
TEST(StaticResultsStore, AnInputFileIsHashedAgainOnlyWhenItsSizeOrTimeChanges) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("lumagraph-static-key-" + std::to_string(getpid()));
  fs::create_directories(folder);
  const std::string file = (folder / "sky.hdr").string();
  const auto write = [&](const std::string& contents) { std::ofstream(file, std::ios::binary) << contents; };
  const StaticResultsStore store(folder.string(), {test_device(), 7});
  const std::vector<std::string> inputs{file};
  // What key_for() gives when it reads the file: its path, then its contents, hashed into the key.
  const auto key_of_contents = [&](const std::string& contents) {
    return static_results_key(static_plan(), {test_device(), 7, fnv1a(contents, fnv1a(file))});
  };

  write("first contents");
  const fs::file_time_type written = fs::last_write_time(file);
  EXPECT_EQ(store.key_for(static_plan(), inputs), key_of_contents("first contents"));
  write("other contents");  // the same size, and the time set back
  fs::last_write_time(file, written);
  EXPECT_EQ(store.key_for(static_plan(), inputs), key_of_contents("first contents")) << "the memo's hash";
  fs::last_write_time(file, written + std::chrono::seconds(1));
  EXPECT_EQ(store.key_for(static_plan(), inputs), key_of_contents("other contents")) << "a new time: read again";
  write("the longest contents");
  fs::last_write_time(file, written + std::chrono::seconds(1));
  EXPECT_EQ(store.key_for(static_plan(), inputs), key_of_contents("the longest contents")) << "a new size: read again";
  fs::remove_all(folder);
}

}  // namespace
}  // namespace lg
