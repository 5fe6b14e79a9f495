// Screen-space occlusion on simple worlds through the whole runtime (G-buffer, then GTAO or
// SSAO), with validation on: an open plane is unoccluded (k_A = 1), a wall standing on the
// floor darkens the floor next to it and not far from it, and temporal accumulation over
// frames stays finite and within [0, 1]. The ray-traced reference comes with the bakes; the
// baked volume (occlusion.bake) feeding lighting.ibl renders cleanly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{160, 120};

Graph occlusion_graph(const std::string& node) {
  const std::string text = R"({ "format": "lumagraph/1", "name": "occlusion-test",
    "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" }, )" +
                           node + R"( ],
    "links": [ { "from": "gbuf.gbuffer", "to": "ao.gbuffer" } ],
    "outputs": [ "ao.ao" ] })";
  Diagnostics d("occlusion-test.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

// A 20 m floor seen from 2 m up at 40 degrees down; optionally a wall across it, 3 m ahead.
World floor_world(bool wall) {
  World world;
  const int white = world.add_material({.name = "white", .base_color = glm::vec4(0.8f), .roughness = 0.8f});
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(20.0f, 20.0f)), white});
  world.add(floor, Transform{});
  if (wall) {
    Entity w = world.create("wall");
    world.add(w, MeshRenderer{world.add_mesh(make_box({6.0f, 2.0f, 0.2f})), white});
    world.add(w, Transform{}).position = {0.0f, 1.0f, -3.0f};
  }
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& view = world.add(camera, Transform{});
  view.position = {0.0f, 2.0f, 0.0f};
  view.rotation = look_rotation({0.0f, -0.64f, -0.77f});
  return world;
}

std::vector<float> render_ao(const std::string& node, const World& world, int frames = 1) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the occlusion is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(occlusion_graph(node));
  for (int f = 0; f < frames; ++f) renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return renderer.executor().read_image("ao.ao");
}

float at(const std::vector<float>& ao, uint32_t x, uint32_t y) {
  return ao[(y * kFrame.width + x) * 4];
}

constexpr const char* kGtao =
    R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "radius": 0.5 } })";
constexpr const char* kSsao = R"({ "id": "ao", "type": "occlusion.ssao", "params": { "radius": 0.5 } })";

// On a plane every horizon is the tangent plane, so the integral is exactly 1; what remains is
// the 8-bit output (1/255) and depth reconstruction of the plane in float.
TEST(Occlusion, GtaoOpenPlaneIsUnoccluded) {
  std::vector<float> ao = render_ao(kGtao, floor_world(false));
  for (uint32_t y = kFrame.height / 2; y < kFrame.height; ++y)  // the lower half sees only floor
    for (uint32_t x = 0; x < kFrame.width; ++x) ASSERT_GE(at(ao, x, y), 0.98f) << x << "," << y;
}

// SSAO's cosine-distributed samples all lie above the plane: none is occluded.
TEST(Occlusion, SsaoOpenPlaneIsUnoccluded) {
  std::vector<float> ao = render_ao(kSsao, floor_world(false));
  for (uint32_t y = kFrame.height / 2; y < kFrame.height; ++y)
    for (uint32_t x = 0; x < kFrame.width; ++x) ASSERT_GE(at(ao, x, y), 0.98f) << x << "," << y;
}

// Where the wall meets the floor the floor sees half its hemisphere's cosine weight blocked
// (0.5 at the crease); within the search radius it must be clearly darker, far away not.
TEST(Occlusion, GtaoDarkensTheCreaseOfAWall) {
  std::vector<float> ao = render_ao(kGtao, floor_world(true), 8);
  float darkest = 1.0f;
  for (float v : ao) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
  }
  // Scan the centre column from the bottom (near floor) upward to the wall's base.
  for (uint32_t y = kFrame.height - 1; y > 0; --y) darkest = std::min(darkest, at(ao, kFrame.width / 2, y));
  EXPECT_LT(darkest, 0.8f);
  EXPECT_GE(at(ao, kFrame.width / 2, kFrame.height - 2), 0.97f) << "the floor near the camera is open";
}

// occlusion.bake's ao and bent normals feed lighting.ibl as GTAO's do: the graph renders with
// zero validation messages over two frames (the second reuses the bake), and occlusion only
// darkens the ambient light, so the frame is darker than the same graph without the links
// (measured 0.985 of the energy: the sky and the open floor fill most of it; the bake is
// deterministic, so 0.99 only leaves room for driver rounding).
double ibl_energy(bool with_bake) {
  const std::string text = R"({ "format": "lumagraph/1", "name": "bake-ibl",
    "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" },
               { "id": "sky", "type": "env.sky" },
               { "id": "sh", "type": "env.sh_project", "params": { "order": 2, "window": "none", "convolve_cosine": true } },
               { "id": "specular", "type": "env.specular_prefilter", "params": { "face_size": 32, "mips": 4, "samples": 32 } },
               { "id": "dfg", "type": "env.brdf_lut" },
               { "id": "bake", "type": "occlusion.bake", "params": { "rays": 32, "resolution": 16 } },
               { "id": "ibl", "type": "lighting.ibl", "params": { "diffuse_source": "sh" } } ],
    "links": [ { "from": "sky.cube", "to": "sh.env" }, { "from": "sky.cube", "to": "specular.env" },
               { "from": "gbuf.gbuffer", "to": "bake.gbuffer" }, { "from": "gbuf.gbuffer", "to": "ibl.gbuffer" },
               { "from": "sh.sh", "to": "ibl.sh" }, { "from": "specular.specular", "to": "ibl.specular" },
               { "from": "dfg.lut", "to": "ibl.brdf_lut" })" +
                           std::string(with_bake ? R"(, { "from": "bake.ao", "to": "ibl.ao" },
               { "from": "bake.bent_normals", "to": "ibl.bent_normals" })"
                                                 : "") +
                           R"( ],
    "outputs": [ "ibl.color", "bake.ao" ] })";
  Diagnostics d("bake-ibl.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;
  Renderer renderer(options);
  renderer.set_graph(std::move(*graph));
  World world = floor_world(true);
  Entity sky = world.create("sky");
  world.add(sky, EnvironmentLight{});  // the procedural sky: lighting.ibl runs only with one
  for (int f = 0; f < 2; ++f) renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  double sum = 0;
  for (float v : renderer.executor().read_image("ibl.color")) {
    EXPECT_TRUE(std::isfinite(v));
    sum += v;
  }
  return sum;
}

TEST(Occlusion, BakedVolumeFeedsImageBasedLighting) {
  const double open = ibl_energy(false), occluded = ibl_energy(true);
  std::printf("ibl energy with the baked occlusion / without: %.4f\n", occluded / open);
  EXPECT_GT(open, 0.0);
  EXPECT_LT(occluded, open * 0.99) << "the crease and the wall's shadowed side lose ambient light";
}

}  // namespace
}  // namespace lg::test
