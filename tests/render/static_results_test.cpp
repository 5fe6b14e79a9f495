// Static results kept on disk (runtime/exec/static_results_store.h) through the library API on
// lavapipe: a second renderer loads them instead of running the static passes and renders the
// same bytes; a changed param, input file or shader build misses; a truncated, corrupt or
// foreign file is ignored with one warning naming it, the passes run, the frame is the same and
// the file is written afresh; results that change every frame (an animated sky) are never kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "api/renderer.h"
#include "tests/render/cache_folders.h"
#include "api/static_results_identity.h"
#include "runtime/exec/static_results_store.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

const std::string kExamples = LUMAGRAPH_SOURCE_DIR "/examples/";
constexpr FrameSize kSmall{64, 36};

// `text` with its first `from` replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// examples/default.json with small cubes and a sampled prefilter, so that the many first frames
// here (each runs the static passes) stay quick; every static node and its resources are kept.
const std::string& quick_graph_text() {
  static const std::string text = [] {
    std::string graph = with(read_file(kExamples + "default.json"), "\"sun_intensity\": 20 }",
                             "\"sun_intensity\": 20, \"face_size\": 32 }");
    return with(graph, "{ \"face_size\": 128, \"mips\": 6 }",
                "{ \"face_size\": 32, \"mips\": 4, \"method\": \"sampled\", \"samples\": 16 }");
  }();
  return text;
}

// That graph written into `folder`: its path.
std::string quick_graph(const fs::path& folder) {
  write_file(folder / "quick.json", quick_graph_text());
  return (folder / "quick.json").string();
}

struct Frame {
  std::vector<float> pixels;
  size_t static_passes = 0, cached = 0;  // of the first frame
  std::vector<std::string> warnings;
};

Frame first_frame(const fs::path& folder, const std::string& graph) {
  Renderer renderer(options_with_cache(folder));
  renderer.load_graph(graph);
  const FrameStats& stats = renderer.render(default_world(), kSmall);
  Frame frame;
  for (size_t p = 0; p < stats.passes.size(); ++p) {
    frame.static_passes += renderer.plan().passes[p].is_static;
    frame.cached += stats.passes[p].cached;
  }
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());
  frame.pixels = renderer.read_output();
  frame.warnings = renderer.take_warnings();
  return frame;
}

std::vector<fs::path> results_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().filename().string().starts_with("static-results-")) files.push_back(entry.path());
  return files;
}

// The key a results file's name gives.
uint64_t key_of(const fs::path& file) {
  return std::stoull(file.filename().string().substr(std::string("static-results-").size(), 16), nullptr, 16);
}

// What the file holds, decoded with that key.
DecodedStaticResults decode(const fs::path& file, const DeviceIdentity& device) {
  return decode_static_results(read_file(file), device, key_of(file));
}

DeviceIdentity this_device() {
  static const DeviceIdentity device = [] {
    RendererOptions options;
    options.pipeline_cache_on_disk = false;
    Renderer renderer(options);
    return device_identity(renderer.context().properties());
  }();
  return device;
}

// The default graph's first frame with an empty cache folder, and the one results file it wrote:
// rendered once, copied into the folders of the tests that start from it.
struct Primed {
  Frame frame;
  std::vector<fs::path> files;
  std::string bytes;  // of the file
};

const Primed& primed() {
  static const Primed primed = [] {
    // A folder of the first test that asks: ctest runs each test in a process of its own, two
    // at a time, and a shared folder was emptied under another process's feet.
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("primed-") + test->test_suite_name() + "-" + test->name();
    std::replace(name.begin(), name.end(), '/', '-');
    const fs::path folder = fresh_folder("static-results", name);
    Primed p;
    p.frame = first_frame(folder, quick_graph(folder));
    p.files = results_files(folder);
    if (p.files.size() == 1) p.bytes = read_file(p.files[0]);
    return p;
  }();
  return primed;
}

// A folder holding the primed results file: what its path there is.
fs::path primed_folder(const std::string& name) {
  const fs::path folder = fresh_folder("static-results", name);
  EXPECT_EQ(primed().files.size(), 1u);
  const fs::path file = folder / primed().files.at(0).filename();
  write_file(file, primed().bytes);
  return file;
}

TEST(StaticResults, ASecondRendererLoadsThemAndRendersTheSameBytes) {
  const Frame& cold = primed().frame;
  EXPECT_GT(cold.static_passes, 0u);
  EXPECT_EQ(cold.cached, 0u);
  ASSERT_EQ(primed().files.size(), 1u) << "written after the first frame";

  const fs::path folder = primed_folder("warm").parent_path();
  const Frame warm = first_frame(folder, quick_graph(folder));
  EXPECT_EQ(warm.cached, warm.static_passes) << "every static pass skipped: its results came from the file";
  EXPECT_TRUE(warm.warnings.empty());
  EXPECT_EQ(warm.pixels, cold.pixels);
}

// The same graph with the sun brighter: another key, so its static passes run and a file of its
// own is written beside the first.
TEST(StaticResults, AChangedParamMisses) {
  const fs::path folder = primed_folder("param").parent_path();
  write_file(folder / "brighter.json", with(quick_graph_text(), "\"sun_intensity\": 20", "\"sun_intensity\": 30"));
  const Frame changed = first_frame(folder, (folder / "brighter.json").string());
  EXPECT_EQ(changed.cached, 0u);
  EXPECT_TRUE(changed.warnings.empty());
  EXPECT_EQ(results_files(folder).size(), 2u);
}

// The environment example with its image rewritten under the same name: the contents are in the
// key, not only the path.
TEST(StaticResults, AChangedInputFileMisses) {
  const fs::path folder = fresh_folder("static-results", "input-file");
  fs::create_directories(folder / "environments");
  std::string graph = read_file(kExamples + "environment.json");  // with small cubes: a quick test
  const std::string large = "\"face_size\": 128";
  for (size_t at = graph.find(large); at != std::string::npos; at = graph.find(large))
    graph.replace(at, large.size(), "\"face_size\": 32");
  write_file(folder / "environment.json", graph);
  auto write_environment = [&](float radiance) {
    std::vector<float> rgba(32 * 16 * 4, radiance);
    save_image((folder / "environments" / "studio.hdr").string(), 32, 16, rgba);
  };
  write_environment(0.5f);
  const Frame dim = first_frame(folder, (folder / "environment.json").string());
  write_environment(2.0f);
  const Frame bright = first_frame(folder, (folder / "environment.json").string());
  EXPECT_EQ(bright.cached, 0u);
  EXPECT_NE(bright.pixels, dim.pixels);
  EXPECT_EQ(results_files(folder).size(), 2u);
}

TEST(StaticResults, AnotherShaderBuildHasAnotherKey) {
  RendererOptions options;
  options.device.validation = true;
  options.pipeline_cache_on_disk = false;
  Renderer renderer(options);
  renderer.load_graph(quick_graph(fresh_folder("static-results", "shader")));
  renderer.render(default_world(), kSmall);
  const DeviceIdentity device = device_identity(renderer.context().properties());
  const StaticResultsStore built("folder", {device, node_code_identity()});
  const StaticResultsStore rebuilt("folder", {device, node_code_identity() ^ 1});
  EXPECT_EQ(built.key_for(renderer.plan(), {}), built.key_for(renderer.plan(), {})) << "stable within a build";
  EXPECT_NE(built.key_for(renderer.plan(), {}), rebuilt.key_for(renderer.plan(), {}));
  ASSERT_EQ(primed().files.size(), 1u);
  EXPECT_EQ(key_of(primed().files[0]), built.key_for(renderer.plan(), {})) << "the key the renderer filed it under";
}

// A file cut short, a flipped byte, a file made for another key under this key's name, results
// that do not fit the plan, a file that is not ours: one warning naming the file and the reason,
// the passes run, the frame is the same, and the file is good again afterwards.
struct BrokenFile {
  const char* name;
  std::function<std::string(const std::string& good, const DeviceIdentity&, uint64_t key)> bytes;
  const char* reason;
};

void PrintTo(const BrokenFile& broken, std::ostream* out) {
  *out << broken.name;
}

class StaticResultsBroken : public testing::TestWithParam<BrokenFile> {};

TEST_P(StaticResultsBroken, IsIgnoredWithOneWarningAndTheFrameIsTheSame) {
  const fs::path file = primed_folder(std::string("broken-") + GetParam().name);
  const DeviceIdentity device = this_device();
  const uint64_t key = key_of(file);
  write_file(file, GetParam().bytes(primed().bytes, device, key));
  const Frame frame = first_frame(file.parent_path(), quick_graph(file.parent_path()));
  ASSERT_EQ(frame.warnings.size(), 1u);
  EXPECT_NE(frame.warnings[0].find(file.string()), std::string::npos) << frame.warnings[0];
  EXPECT_NE(frame.warnings[0].find(GetParam().reason), std::string::npos) << frame.warnings[0];
  EXPECT_EQ(frame.cached, 0u);
  EXPECT_EQ(frame.pixels, primed().frame.pixels);
  EXPECT_EQ(decode(file, device).problem, "") << "written afresh after the frame";
}

std::vector<StoredResult> results_of(const std::string& good, const DeviceIdentity& device, uint64_t key) {
  return decode_static_results(good, device, key).results;
}

INSTANTIATE_TEST_SUITE_P(
    StaticResults, StaticResultsBroken,
    testing::Values(BrokenFile{"truncated",
                               [](const std::string& good, auto&, uint64_t) { return good.substr(0, good.size() / 2); },
                               "truncated"},
                    BrokenFile{"flipped",
                               [](std::string good, auto&, uint64_t) {
                                 good[good.size() / 2] ^= 1;
                                 return good;
                               },
                               "checksum"},
                    BrokenFile{"foreign",
                               [](const std::string& good, const DeviceIdentity& device, uint64_t key) {
                                 return encode_static_results(device, key ^ 1, results_of(good, device, key));
                               },
                               "another key"},
                    BrokenFile{"misfit",
                               [](const std::string& good, const DeviceIdentity& device, uint64_t key) {
                                 std::vector<StoredResult> results = results_of(good, device, key);
                                 results[0].name += "-elsewhere";
                                 return encode_static_results(device, key, results);
                               },
                               "-elsewhere"},
                    BrokenFile{"not-ours", [](auto&, auto&, uint64_t) { return std::string(4096, 'x'); },
                               "wrong magic"}),
    [](const testing::TestParamInfo<BrokenFile>& info) {
      std::string name = info.param.name;
      std::erase(name, '-');
      return name;
    });

// Room for one file only: writing the brighter sky's results removes the default's, the least
// recently used, and never the file just written.
TEST(StaticResults, TheFolderKeepsTheMostRecentlyUsedWithinItsBound) {
  const fs::path older = primed_folder("bound");
  const fs::path folder = older.parent_path();
  write_file(folder / "brighter.json", with(quick_graph_text(), "\"sun_intensity\": 20", "\"sun_intensity\": 30"));
  RendererOptions options = options_with_cache(folder);
  options.static_results_max_bytes = fs::file_size(older) * 3 / 2;
  Renderer renderer(options);
  renderer.load_graph((folder / "brighter.json").string());
  renderer.render(default_world(), kSmall);
  const std::vector<fs::path> kept = results_files(folder);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NE(kept[0], older);
  EXPECT_EQ(decode(kept[0], this_device()).problem, "");
}

// env.sky with sun_turn_speed renders a new sky every frame: its cube, SH and prefiltered cube
// are not static, and only the BRDF table (static in every graph) is kept.
TEST(StaticResults, AnAnimatedSkyIsNeverKept) {
  const fs::path folder = fresh_folder("static-results", "animated");
  first_frame(folder, kExamples + "animated-sky.json");
  ASSERT_EQ(results_files(folder).size(), 1u);
  const DecodedStaticResults kept = decode(results_files(folder)[0], this_device());
  ASSERT_EQ(kept.problem, "");
  ASSERT_EQ(kept.results.size(), 1u);
  EXPECT_EQ(kept.results[0].name, "dfg.lut");
  const Frame again = first_frame(folder, kExamples + "animated-sky.json");
  EXPECT_EQ(again.cached, again.static_passes);
  EXPECT_LT(again.static_passes, 2u) << "the sky's passes are not static";
}

}  // namespace
}  // namespace lg::test
