// The pipeline cache through the library API on lavapipe: every plan a renderer compiles (a
// resize, a hot reload) reuses the pipelines the last one made; the driver's cache is saved to
// disk and a second renderer hands it back to the driver; a truncated, corrupt or foreign file
// is ignored with one warning naming the file, and an unwritable folder costs one warning: in
// every case the frame is bit-identical to one rendered with no disk cache at all.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "api/renderer.h"
#include "tests/render/cache_folders.h"
#include "graph/fault_injection.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/pipeline_cache_file.h"
#include "runtime/scene/default_world.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

const std::string kGraph = LUMAGRAPH_SOURCE_DIR "/examples/default.json";
constexpr FrameSize kSmall{64, 36}, kLarger{96, 54};

std::vector<float> first_frame(Renderer& renderer) {
  renderer.load_graph(kGraph);
  renderer.render(default_world(), kSmall);
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
  return renderer.read_output();
}

// The frame of a renderer that keeps no cache on disk: what every other must render.
const std::vector<float>& reference_frame() {
  static const std::vector<float> frame = [] {
    RendererOptions options;
    options.device.validation = true;
    options.pipeline_cache_on_disk = false;
    Renderer renderer(options);
    EXPECT_EQ(renderer.pipeline_cache_store(), nullptr);
    return first_frame(renderer);
  }();
  return frame;
}

TEST(PipelineCache, ARecompileReusesThePipelinesOfTheLastPlan) {
  RendererOptions options;
  options.device.validation = true;
  options.pipeline_cache_on_disk = false;
  Renderer renderer(options);
  first_frame(renderer);
  const uint64_t made = renderer.context().pipelines().created();
  EXPECT_GT(made, 10u) << "the default graph makes its pipelines through the context's cache";

  renderer.render(default_world(), kLarger);  // a resize: a new plan and executor
  EXPECT_EQ(renderer.context().pipelines().created(), made);
  renderer.reload_graph();  // a hot reload: another plan and executor
  renderer.render(default_world(), kSmall);
  EXPECT_EQ(renderer.context().pipelines().created(), made);
  EXPECT_EQ(renderer.read_output(), reference_frame());
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
}

TEST(PipelineCache, ASecondRendererHandsTheSavedCacheToTheDriver) {
  const fs::path folder = fresh_folder("pipeline-cache", "warm");
  std::vector<std::byte> saved;
  std::string path;
  {
    Renderer cold(options_with_cache(folder));
    ASSERT_NE(cold.pipeline_cache_store(), nullptr);
    EXPECT_EQ(cold.pipeline_cache_store()->loaded_bytes(), 0u) << "nothing to load on the first run";
    EXPECT_EQ(first_frame(cold), reference_frame());
    EXPECT_TRUE(cold.take_warnings().empty());
    path = cold.pipeline_cache_store()->path();
    EXPECT_TRUE(fs::exists(path)) << "saved after the first frame, before the renderer goes";
    saved = cold.context().pipelines().driver_data();
  }
  ASSERT_FALSE(saved.empty());
  EXPECT_EQ(fs::path(path).parent_path(), folder);

  Renderer warm(options_with_cache(folder));
  EXPECT_TRUE(warm.take_warnings().empty());
  EXPECT_EQ(decode_pipeline_cache(read_file(path), device_identity(warm.context().properties())).driver_data, saved);
  EXPECT_EQ(warm.pipeline_cache_store()->loaded_bytes(), saved.size());
  EXPECT_EQ(first_frame(warm), reference_frame());
  EXPECT_TRUE(warm.take_warnings().empty());
}

// A file cut short, a flipped byte, another device's cache under this device's name, a file that
// is not ours: each gives one warning naming the file and what was wrong, the frame is the same,
// and the file is written afresh after it.
TEST(PipelineCache, ABrokenFileIsIgnoredWithOneWarningAndTheFrameIsTheSame) {
  const fs::path folder = fresh_folder("pipeline-cache", "broken");
  std::string path, good;
  DeviceIdentity device;
  {
    Renderer renderer(options_with_cache(folder));
    first_frame(renderer);
    path = renderer.pipeline_cache_store()->path();
    device = device_identity(renderer.context().properties());
  }
  good = read_file(path);
  ASSERT_EQ(decode_pipeline_cache(good, device).problem, "");
  DeviceIdentity other = device;
  other.cache_uuid[3] ^= 0x40;
  std::string flipped = good;
  flipped.back() = char(flipped.back() ^ 1);

  const std::pair<std::string, std::string> broken[] = {
      {good.substr(0, good.size() / 2), "truncated"},
      {flipped, "checksum"},
      {encode_pipeline_cache(other, decode_pipeline_cache(good, device).driver_data), "another device or driver"},
      {"{ \"format\": \"lumagraph/1\" }", "truncated"},
      {std::string(4096, 'x'), "wrong magic"},
  };
  for (const auto& [bytes, reason] : broken) {
    SCOPED_TRACE(reason);
    write_file(path, bytes);
    Renderer renderer(options_with_cache(folder));
    const std::vector<std::string> warnings = renderer.take_warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find(path), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find(reason), std::string::npos) << warnings[0];
    EXPECT_EQ(renderer.pipeline_cache_store()->loaded_bytes(), 0u);
    EXPECT_EQ(first_frame(renderer), reference_frame());
    EXPECT_TRUE(renderer.take_warnings().empty());
    EXPECT_EQ(decode_pipeline_cache(read_file(path), device).problem, "") << "written afresh after the frame";
  }
}

// Root writes into read-only folders, so the folder is made impossible instead: a path through a
// regular file. And a disk that fills up while the file is written (an injected ENOSPC).
TEST(PipelineCache, AnUnwritableFolderDoesNotFailTheRender) {
  const fs::path blocker = fresh_folder("pipeline-cache", "unwritable") / "a-file";
  write_file(blocker, "not a folder");
  {
    Renderer renderer(options_with_cache(blocker / "cache"));
    EXPECT_EQ(first_frame(renderer), reference_frame());
    std::vector<std::string> warnings = renderer.take_warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("not saved"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find((blocker / "cache").string()), std::string::npos) << warnings[0];
    renderer.render(default_world(), kLarger);
    EXPECT_TRUE(renderer.take_warnings().empty()) << "one warning, not one per plan";
  }

  const fs::path folder = fresh_folder("pipeline-cache", "full-disk");
  arm_fault(FaultSite::file_write, 1);
  Renderer renderer(options_with_cache(folder));
  EXPECT_EQ(first_frame(renderer), reference_frame());
  arm_fault(FaultSite::file_write, 0);
  const std::vector<std::string> warnings = renderer.take_warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("No space left on device"), std::string::npos) << warnings[0];
  EXPECT_TRUE(fs::is_empty(folder)) << "no file, no temporary file left";
}

TEST(PipelineCache, TheEnvironmentTurnsItOff) {
  const fs::path folder = fresh_folder("pipeline-cache", "off");
  ::setenv("LUMAGRAPH_PIPELINE_CACHE", "off", 1);
  {
    Renderer renderer(options_with_cache(folder));
    EXPECT_EQ(renderer.pipeline_cache_store(), nullptr);
    first_frame(renderer);
  }
  ::unsetenv("LUMAGRAPH_PIPELINE_CACHE");
  EXPECT_TRUE(fs::is_empty(folder));
}

}  // namespace
}  // namespace lg::test
