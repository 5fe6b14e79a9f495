// The white furnace through a whole frame: white spheres (albedo 1; dielectric and metal,
// roughness 0 to 1 in steps of 0.1) lit only by examples/environment.json's image-based light,
// its env.load reading a constant environment of radiance 1 written by the test. Every pixel of
// every sphere, silhouettes (grazing views) included, must show radiance 1 within 1%, the issue's
// criterion. What remains: ibl.color's half floats (4.9e-4), the SH irradiance's float sums and
// the prefilter's normalisation; the DFG table's resolution does not enter, as diffuse and
// specular read the same texel (the direct-light furnace, where it does, is
// tests/lighting/brdf_furnace_gpu_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{352, 96};
constexpr int kRoughnessSteps = 10;

// Two rows of eleven spheres: dielectrics above, metals below, roughness rising to the right.
World white_spheres() {
  World world;
  const int mesh = world.add_mesh(make_sphere(0.45f, 96, 48));
  for (int metal = 0; metal < 2; ++metal)
    for (int r = 0; r <= kRoughnessSteps; ++r) {
      PbrMaterial white;
      white.base_color = glm::vec4(1.0f);
      white.roughness = float(r) / kRoughnessSteps, white.metalness = float(metal);
      Entity sphere = world.create("sphere");
      world.add(sphere, MeshRenderer{mesh, world.add_material(white)});
      Transform& t = world.add(sphere, Transform{});
      t.position = glm::vec3(float(r - 5), metal ? -0.5f : 0.5f, 0.0f);
    }
  Entity sky = world.create("sky");
  world.add(sky, EnvironmentLight{});  // lighting.ibl runs only with one; the graph names the file
  Entity camera = world.create("camera");
  world.add(camera, Camera{.vertical_fov = 0.42f});
  Transform& t = world.add(camera, Transform{});
  t.position = glm::vec3(0.0f, 0.0f, 8.0f);
  t.rotation = look_rotation({0.0f, 0.0f, -1.0f});
  return world;
}

// examples/environment.json with every env.load reading `environment`.
Graph environment_graph(const std::string& environment) {
  Diagnostics d("examples/environment.json");
  std::optional<Graph> graph = load_graph_file("examples/environment.json", d);
  if (!graph) throw std::runtime_error(d.to_string());
  for (GraphNode& node : graph->nodes)
    if (node.type == "env.load") node.params.set("path", environment);
  return std::move(*graph);
}

TEST(WhiteFurnace, WhiteSpheresShowAConstantEnvironmentInImageBasedLight) {
  const std::filesystem::path folder = std::filesystem::path(LUMAGRAPH_BINARY_DIR) / "white-furnace";
  std::filesystem::create_directories(folder);
  const std::string environment = (folder / "white.hdr").string();
  save_image(environment, 64, 32, std::vector<float>(64 * 32 * 4, 1.0f));  // RGBE holds 1 exactly

  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the G-buffer and ibl.color are read after the frame
  options.asset_roots.roots = {folder.string()};
  Renderer renderer(options);
  renderer.set_graph(environment_graph(environment));
  renderer.render(white_spheres(), kFrame);
  const std::vector<float> lit = renderer.executor().read_image("ibl.color");
  const std::vector<float> depth = renderer.executor().read_image("gbuf.gbuffer.depth");
  const std::vector<float> material = renderer.executor().read_image("gbuf.gbuffer.material");
  EXPECT_TRUE(renderer.context().take_validation_messages().empty());

  struct Group {
    double sum = 0, low = 1e9, high = -1e9;
    size_t pixels = 0;
  };
  Group groups[2][kRoughnessSteps + 1];
  double worst = 0.0;
  for (size_t p = 0; p < size_t(kFrame.width) * kFrame.height; ++p) {
    if (!(depth[4 * p] > 0.0f)) continue;  // the sky
    const int r = int(std::lround(material[4 * p] * kRoughnessSteps)), metal = material[4 * p + 1] > 0.5f ? 1 : 0;
    Group& g = groups[metal][r];
    for (int c = 0; c < 3; ++c) {
      const double v = lit[4 * p + c];
      g.sum += v / 3, g.low = std::min(g.low, v), g.high = std::max(g.high, v);
      worst = std::max(worst, std::abs(v - 1.0));
    }
    ++g.pixels;
  }
  std::printf("white furnace, image-based light of a constant environment of 1 (examples/environment.json)\n");
  std::printf("%-9s %9s %8s %8s %8s\n", "", "roughness", "mean", "min", "max");
  for (int metal = 0; metal < 2; ++metal)
    for (int r = 0; r <= kRoughnessSteps; ++r) {
      const Group& g = groups[metal][r];
      EXPECT_GT(g.pixels, 300u) << "metal " << metal << ", roughness " << r;
      std::printf("%-9s %9.1f %8.4f %8.4f %8.4f\n", metal ? "metal" : "dielectric", double(r) / kRoughnessSteps,
                  g.sum / double(std::max<size_t>(g.pixels, 1)), g.low, g.high);
    }
  std::printf("max |radiance - 1| = %.5f\n", worst);
  EXPECT_LE(worst, 0.01);
}

}  // namespace
}  // namespace lg::test
