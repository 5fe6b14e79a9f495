// Screen-space occlusion on simple worlds through the whole runtime (G-buffer, then GTAO or
// SSAO), with validation on: an open plane is unoccluded (k_A = 1), a wall standing on the
// floor darkens the floor next to it and not far from it, and temporal accumulation over
// frames stays finite and within [0, 1]. The ray-traced reference comes with the bakes.
#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace lg::test
