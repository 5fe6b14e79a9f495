// Frustum culling of draws in scene.gbuffer: boxes in view, straddling each edge of the view,
// beside it and behind the camera, which looks away from the origin (so a box tested where its
// mesh stands rather than where its draw puts it would be culled wrongly). The lit image is the
// same, bit for bit, with culling on and off: culling leaves out only what could not be seen.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "api/renderer.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/render/deferred_graph.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{96, 64};

// The camera at (20, 1, 0) looks down -Z at a wall of boxes 6 m away; a sun lights them.
World boxes_around_the_view() {
  World world;
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  world.add(camera, Transform{.position = {20.0f, 1.0f, 0.0f}, .rotation = look_rotation({0.0f, 0.0f, -1.0f})});
  Entity sun = world.create("sun");
  world.add(sun, DirectionalLight{});
  world.add(sun, Transform{.rotation = look_rotation({0.3f, -0.6f, -0.5f})});
  const int box = world.add_mesh(make_box({1.0f, 1.0f, 1.0f}));
  // At 6 m, 50 degrees and 3:2 the view spans +-2.8 m up and +-4.2 m across: boxes in the
  // middle, on each edge, beyond each edge and behind the camera.
  for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(4.2f, 0, 0), glm::vec3(-4.2f, 0, 0), glm::vec3(0, 2.8f, 0),
                      glm::vec3(0, -2.8f, 0), glm::vec3(9, 0, 0), glm::vec3(0, -9, 0), glm::vec3(0, 0, 12)}) {
    Entity e = world.create();
    world.add(e, MeshRenderer{box, -1});
    world.add(e, Transform{.position = glm::vec3(20.0f, 1.0f, -6.0f) + p});
  }
  return world;
}

std::vector<float> render(const World& world, bool culling) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the lighting is read back after the frame
  Renderer renderer(options);
  Graph graph = deferred_lighting_graph();
  for (GraphNode& node : graph.nodes)
    if (node.id == "gbuf") node.params.set("frustum_culling", culling);
  renderer.set_graph(std::move(graph));
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return renderer.executor().read_image("light.color");
}

TEST(DrawCulling, CullingChangesNoPixel) {
  const World world = boxes_around_the_view();
  const std::vector<float> culled = render(world, true);
  const size_t lit = size_t(std::count_if(culled.begin(), culled.end(), [](float v) { return v > 0.0f; }));
  EXPECT_GT(lit, 0u);
  EXPECT_EQ(culled, render(world, false));
}

}  // namespace
}  // namespace lg::test
