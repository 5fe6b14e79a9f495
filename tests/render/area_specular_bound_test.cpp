// No area light reflects more than the whole specular lobe would of its radiance: a white metal
// floor (albedo 1, roughness 0.18) under a 20 m square light of radiance 2 a metre above it, which
// covers nearly all of every floor pixel's lobe, through lighting.deferred with either specular
// method. A white metal's lobe reflects its whole light (the multiple-scattering compensation
// makes its directional albedo 1: the white furnace), so every floor pixel must read at most 2,
// within 1% (half floats, the albedo table's interpolation), and LTC at least 90% of it (the
// light leaves the lobe's grazing tail uncovered; measured 1.90). Before area_lights.glsl bounded
// it, the representative point read up to 30.5 here (mean 11.8): a narrow lobe's peak over the
// light's whole solid angle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"
#include "tests/render/deferred_graph.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{64, 48};
constexpr float kRadiance = 2.0f;

World metal_floor_under_a_wide_light() {
  World world;
  PbrMaterial metal;
  metal.base_color = glm::vec4(1.0f), metal.metalness = 1.0f, metal.roughness = 0.18f;
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(8.0f, 8.0f)), world.add_material(metal)});
  world.add(floor, Transform{});
  Entity lamp = world.create("lamp");
  world.add(lamp, RectLight{.intensity = kRadiance, .width = 20.0f, .height = 20.0f, .casts_shadows = false});
  Transform& at = world.add(lamp, Transform{});
  at.position = {0.0f, 1.0f, 0.0f}, at.rotation = look_rotation({0.0f, -1.0f, 0.0f});
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& eye = world.add(camera, Transform{});
  eye.position = {0.0f, 0.6f, 3.0f}, eye.rotation = look_rotation({0.0f, -0.35f, -1.0f});
  return world;
}

TEST(AreaSpecular, NoLightReflectsMoreThanTheWholeLobe) {
  const World world = metal_floor_under_a_wide_light();
  for (const std::string method : {"ltc", "representative_point"}) {
    RendererOptions options;
    options.device.validation = true;
    options.alias = false;  // light.color is read back after the frame
    Renderer renderer(options);
    renderer.set_graph(deferred_lighting_graph(R"({ "area_specular": ")" + method + R"(" })"));
    renderer.render(world, kFrame);
    const std::vector<float> color = renderer.executor().read_image("light.color");
    const std::vector<float> depth = renderer.executor().read_image("gbuf.gbuffer.depth");
    double largest = 0, sum = 0;
    size_t floor = 0;
    for (size_t i = 0; i < depth.size() / 4; ++i) {
      if (!(depth[4 * i] > 0.0f)) continue;  // the sky
      for (int c = 0; c < 3; ++c) largest = std::max(largest, double(color[4 * i + size_t(c)]));
      sum += color[4 * i + 1], ++floor;
    }
    const double mean = sum / double(std::max<size_t>(floor, 1));
    std::printf("%s: %zu floor pixels, largest %.4f, mean %.4f (the lobe's whole: %.1f)\n", method.c_str(), floor,
                largest, mean, kRadiance);
    EXPECT_GT(floor, size_t(kFrame.width) * kFrame.height / 4) << method;
    EXPECT_LE(largest, 1.01 * kRadiance) << method;
    if (method == "ltc") {
      EXPECT_GE(mean, 0.9 * kRadiance);
    }
    auto messages = renderer.context().take_validation_messages();
    EXPECT_TRUE(messages.empty()) << method << ": " << messages.size() << " validation message(s)";
  }
}

}  // namespace
}  // namespace lg::test
