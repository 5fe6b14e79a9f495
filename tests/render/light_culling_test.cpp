// Light culling in lighting.deferred (nodes/lighting/deferred/light_culling.h): which point and
// spot lights reach the camera's frustum, that a culled light leaves the shadow budget to the
// lights in view, and two renders: a light whose range cannot reach the view changes no pixel,
// and a light outside the view whose range reaches visible surfaces is still shaded (the image
// is the same, bit for bit, with culling on and off). No tolerance: the range window is exactly
// 0 past the range, so culling must not change a single bit.
#include "nodes/lighting/deferred/light_culling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "api/renderer.h"
#include "nodes/lighting/deferred/light_buffers.h"
#include "nodes/lighting/deferred/local_shadows.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/projection.h"
#include "tests/render/deferred_graph.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

// At the origin looking down -Z, 90 degrees wide.
SceneView camera_at_origin() {
  SceneView scene;
  scene.camera.projection = reversed_z_infinite_perspective(1.5707964f, 1.0f, 0.1f);
  return scene;
}

TEST(LightCulling, RangeSpheresOutsideTheViewAreCulled) {
  const Frustum f = view_frustum(camera_at_origin().camera);
  EXPECT_TRUE(reaches(f, PointLightData{.position = {0, 0, -5}, .range = 1.0f}));
  EXPECT_FALSE(reaches(f, PointLightData{.position = {0, 0, 5}, .range = 1.0f}));    // behind
  EXPECT_TRUE(reaches(f, PointLightData{.position = {0, 0, 5}, .range = 6.0f}));     // behind, reaching in
  EXPECT_TRUE(reaches(f, PointLightData{.position = {0, 0, 5}, .range = 0.0f}));     // no range: everywhere
  EXPECT_FALSE(reaches(f, PointLightData{.position = {20, 0, -5}, .range = 5.0f}));  // beside
  EXPECT_TRUE(reaches(f, PointLightData{.position = {20, 0, -5}, .range = 12.0f}));  // 10.6 m from the plane
  EXPECT_FALSE(reaches(f, SpotLightData{.position = {0, 0, 5}, .range = 1.0f}));
}

// A spot's cone (cut by its range where it has one) against the same 90-degree view down -Z:
// behind the camera, one aiming at the view reaches it at any range that gets there, one
// aiming away never does, even without a range; one aiming across reaches it when its cone is
// wide enough to tip into the view.
TEST(LightCulling, SpotConesOutsideTheViewAreCulled) {
  const Frustum f = view_frustum(camera_at_origin().camera);
  const glm::vec3 forward(0, 0, -1), back(0, 0, 1), up(0, 1, 0);
  auto spot = [](glm::vec3 position, glm::vec3 direction, float outer_degrees, float range) {
    return SpotLightData{
        .position = position, .direction = direction, .range = range, .outer_cone_angle = glm::radians(outer_degrees)};
  };
  EXPECT_TRUE(reaches(f, spot({0, 0, 5}, forward, 30, 0)));
  EXPECT_TRUE(reaches(f, spot({0, 0, 5}, forward, 30, 6)));
  EXPECT_FALSE(reaches(f, spot({0, 0, 5}, forward, 30, 4)));  // its range ends behind the camera
  EXPECT_FALSE(reaches(f, spot({0, 0, 5}, back, 30, 0)));     // aims away: no range needed
  EXPECT_FALSE(reaches(f, spot({0, 0, 5}, back, 80, 0)));
  // 10 m above the view's axis, 5 m ahead (above its top plane y = -z), aiming up: the
  // 30-degree cone never turns down into the view; the 90-degree one, the half space y >= 10,
  // meets it farther ahead, where the view is more than 10 m tall.
  EXPECT_FALSE(reaches(f, spot({0, 10, -5}, up, 30, 0)));
  EXPECT_TRUE(reaches(f, spot({0, 10, -5}, up, 90, 0)));
  // There aiming forward, level: the cone's lower edge, 30 degrees down, enters the view 3.7 m
  // out, so a range of 5 m reaches it and one of 3 m does not.
  EXPECT_TRUE(reaches(f, spot({0, 10, -5}, forward, 30, 0)));
  EXPECT_TRUE(reaches(f, spot({0, 10, -5}, forward, 30, 5)));
  EXPECT_FALSE(reaches(f, spot({0, 10, -5}, forward, 30, 3)));
}

TEST(LightCulling, CulledLightsLeaveTheShadowBudgetToLightsInView) {
  SceneView scene = camera_at_origin();
  scene.point_lights.push_back({.position = {0, 0, 3}, .range = 1.0f});    // nearest, behind the camera
  scene.point_lights.push_back({.position = {0, 0, -10}, .range = 1.0f});  // in view
  scene.spot_lights.push_back({.position = {0, 30, 0}, .range = 2.0f});    // far above the view
  scene.sphere_lights.push_back({.center = {0, 0, 100}});                  // no cut-off: kept
  const SceneView lights = lights_in_view(scene);
  ASSERT_EQ(lights.point_lights.size(), 1u);
  EXPECT_EQ(lights.point_lights[0].position.z, -10.0f);
  EXPECT_TRUE(lights.spot_lights.empty());
  EXPECT_EQ(lights.sphere_lights.size(), 1u);
  EXPECT_EQ(plan_local_shadows(lights, 1, 1024).point_first_view, (std::vector<int>{0}));
  // Without culling the budget of one goes to the nearest light, which lights nothing in view.
  const SceneView all = lights_in_view(scene, false);
  EXPECT_EQ(all.point_lights.size(), 2u);
  EXPECT_EQ(plan_local_shadows(all, 1, 1024).point_first_view, (std::vector<int>{0, -1}));
}

constexpr FrameSize kFrame{64, 64};

// A floor seen from 4 m straight above (50 degrees: it shows x and z within 1.87 m of the
// origin); point lights added by the tests.
World floor_seen_from_above() {
  World world;
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(30.0f, 30.0f)), -1});
  world.add(floor, Transform{});
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  world.add(camera, Transform{.position = {0.0f, 4.0f, 0.0f},
                              .rotation = look_rotation({0.0f, -1.0f, 0.0f}, {0.0f, 0.0f, -1.0f})});
  return world;
}

void add_point(World& world, glm::vec3 position, float range) {
  Entity e = world.create();
  world.add(e, PointLight{.intensity = 10.0f, .range = range});
  world.add(e, Transform{.position = position});
}

// Outside the view (at 0.5 m up the view is 1.63 m to each side) but 1.2 m from the floor's
// visible edge, well within its range of 4 m.
void add_light_reaching_the_view(World& world) {
  add_point(world, {3.0f, 0.5f, 0.0f}, 4.0f);
}

std::vector<float> render(const World& world, bool cull) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // the lighting is read back after the frame
  Renderer renderer(options);
  renderer.set_graph(deferred_lighting_graph(std::string(R"({ "cull_lights": )") + (cull ? "true" : "false") + " }"));
  renderer.render(world, kFrame);
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return renderer.executor().read_image("light.color");
}

TEST(LightCullingRender, LightOutsideTheViewThatReachesItIsShaded) {
  World world = floor_seen_from_above();
  add_light_reaching_the_view(world);
  const std::vector<float> culled = render(world, true);
  const size_t lit = size_t(std::count_if(culled.begin(), culled.end(), [](float v) { return v > 0.0f; }));
  EXPECT_GT(lit, culled.size() / 4) << "the light reaches the floor in view";
  EXPECT_EQ(culled, render(world, false));
}

TEST(LightCullingRender, LightThatCannotReachTheViewChangesNoPixel) {
  World world = floor_seen_from_above();
  add_light_reaching_the_view(world);
  const std::vector<float> before = render(world, true);
  add_point(world, {12.0f, 0.5f, 0.0f}, 2.0f);  // 9 m from the view's side plane
  add_point(world, {0.0f, 7.0f, 0.0f}, 2.5f);   // behind the camera
  EXPECT_EQ(render(world, true), before);
}

// The lists are uniform blocks of kMaxLightsPerKind lights a kind: that many in view render
// (validation-clean), one more fails the frame with an error naming the kind and the count.
TEST(LightCullingRender, MoreLightsOfAKindInViewThanTheListHoldsIsAnErrorNamingThem) {
  World world = floor_seen_from_above();
  for (size_t i = 0; i < kMaxLightsPerKind; ++i) add_point(world, {0.01f * float(i), 0.5f, 0.0f}, 0.0f);
  EXPECT_FALSE(render(world, true).empty());
  add_point(world, {0.0f, 0.6f, 0.0f}, 0.0f);
  try {
    render(world, true);
    ADD_FAILURE() << "one light more than the list holds rendered";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("at most 256 point lights"), std::string::npos) << what;
    EXPECT_NE(what.find("has 257"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lg::test
