// A light whose colour is NaN or Inf in one channel (a host's bug) must not spread it: the
// deferred passes write 0 where a texel's radiance is not finite, so every texel of their HDR
// output stays finite, on a floor that both lights reach.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/render/deferred_graph.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{96, 64};

// A floor seen from above, a point light with a NaN red channel and a sphere light with an
// infinite green one, both over the floor.
World floor_with_broken_lights() {
  World world;
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(20.0f, 20.0f)), -1});
  world.add(floor, Transform{});
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& view = world.add(camera, Transform{});
  view.position = {0.0f, 2.0f, 0.0f};
  view.rotation = look_rotation({0.0f, -0.64f, -0.77f});
  Entity point = world.create("nan-point");
  world.add(point, PointLight{.color = {std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f}, .intensity = 5.0f});
  world.add(point, Transform{}).position = {0.0f, 1.0f, -3.0f};
  Entity sphere = world.create("inf-sphere");
  world.add(sphere, SphereLight{.color = {1.0f, std::numeric_limits<float>::infinity(), 1.0f}, .radius = 0.2f});
  world.add(sphere, Transform{}).position = {1.0f, 1.0f, -4.0f};
  return world;
}

TEST(NonFiniteLight, OneBadChannelLeavesTheLightingFinite) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the lighting is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(deferred_lighting_graph());
  renderer.render(floor_with_broken_lights(), kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  const std::vector<float> color = renderer.executor().read_image("light.color");
  ASSERT_EQ(color.size(), size_t{kFrame.width} * kFrame.height * 4);
  size_t non_finite = 0;
  for (float v : color) non_finite += !std::isfinite(v);
  EXPECT_EQ(non_finite, 0u);
}

}  // namespace
}  // namespace lg::test
