// Broken input at run time ends in an error that names the file or the pass, never a crash or a
// silently black image: a truncated or corrupt environment image (HDR, EXR) behind env.load,
// and the device running out of memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "api/renderer.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"

namespace lg::test {
namespace {

namespace fs = std::filesystem;

// A folder of its own for the graph and its environment file (paths resolve next to the graph).
struct Folder {
  fs::path path = fs::temp_directory_path() /
                  ("lumagraph-broken-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Folder() { fs::create_directories(path); }
  ~Folder() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path / name, std::ios::binary) << bytes;
    return (path / name).string();
  }
};

std::string environment_graph(const std::string& file) {
  return R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "env", "type": "env.load", "params": { "path": ")" +
         file + R"(", "face_size": 16 } },
      { "id": "sh", "type": "env.sh_project", "params": { "convolve_cosine": true } },
      { "id": "specular", "type": "env.specular_prefilter", "params": { "face_size": 16, "mips": 3 } },
      { "id": "dfg", "type": "env.brdf_lut", "params": { "size": 16 } }, { "id": "ibl", "type": "lighting.ibl" },
      { "id": "out", "type": "output.display" } ],
    "links": [ { "from": "env.cube", "to": "sh.env" }, { "from": "env.cube", "to": "specular.env" },
               { "from": "gbuf.gbuffer", "to": "ibl.gbuffer" }, { "from": "sh.sh", "to": "ibl.sh" },
               { "from": "specular.specular", "to": "ibl.specular" }, { "from": "dfg.lut", "to": "ibl.brdf_lut" },
               { "from": "ibl.color", "to": "out.color" } ] })";
}

// Renders the graph on the default world and returns the error message (empty: no error).
std::string render_error(const Folder& folder, const std::string& environment) {
  const std::string graph = folder.write("graph.json", environment_graph(environment));
  Renderer renderer;
  renderer.load_graph(graph);
  World world = default_world();
  try {
    renderer.render(world, {64, 36});
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

TEST(BrokenInput, TruncatedHdrNamesTheFile) {
  Folder folder;
  std::vector<float> pixels(32 * 16 * 4, 1.0f);
  save_image((folder.path / "whole.hdr").string(), 32, 16, pixels);
  std::ifstream in(folder.path / "whole.hdr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  folder.write("cut.hdr", bytes.substr(0, bytes.size() / 3));
  const std::string error = render_error(folder, "cut.hdr");
  EXPECT_NE(error.find("cut.hdr"), std::string::npos) << error;
  EXPECT_NE(error.find("truncated or corrupt"), std::string::npos) << error;
}

TEST(BrokenInput, CorruptExrNamesTheFile) {
  Folder folder;
  folder.write("noise.exr", std::string("\x76\x2f\x31\x01\x02\x00\x00\x00garbage that is no EXR header", 37));
  const std::string error = render_error(folder, "noise.exr");
  EXPECT_NE(error.find("noise.exr"), std::string::npos) << error;
}

// An allocation far beyond the device's memory: the Vulkan error comes back as a GpuError that
// names the call and the buffer. (No validation here: the layer rightly objects to the size.)
TEST(BrokenInput, OutOfDeviceMemoryNamesTheResource) {
  Context context;
  try {
    Buffer::dedicated(context, {.name = "enormous", .size = uint64_t{1} << 46});
    FAIL() << "a 64 TiB buffer was allocated";
  } catch (const GpuError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("enormous"), std::string::npos) << what;
    EXPECT_NE(e.result(), VK_SUCCESS) << what;
  }
}

}  // namespace
}  // namespace lg::test
