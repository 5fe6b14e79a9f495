// The embedded default world: its summary is the compiler's default_scene_summary(), its
// meshes are well formed, and its camera frames the room's contents at 16:9.
#include "runtime/scene/default_world.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/mesh_tools.h"

namespace lg {
namespace {

TEST(DefaultWorld, SummaryIsTheCompilersDefaultSceneSummary) {
  SceneSummary s = make_scene_view(default_world(), 16.0f / 9.0f).summary();
  SceneSummary expected = default_scene_summary();
  EXPECT_EQ(s.name, expected.name);
  EXPECT_EQ(s.directional_lights, expected.directional_lights);
  EXPECT_EQ(s.point_lights, expected.point_lights);
  EXPECT_EQ(s.sphere_lights, expected.sphere_lights);
  EXPECT_EQ(s.tube_lights, expected.tube_lights);
  EXPECT_EQ(s.rectangle_lights, expected.rectangle_lights);
  EXPECT_EQ(s.shadows, expected.shadows);
  EXPECT_EQ(s.environment, expected.environment);
  EXPECT_EQ(s.irradiance_volumes, expected.irradiance_volumes);
  EXPECT_EQ(s.reflection_probes, expected.reflection_probes);
  EXPECT_EQ(s.glossy_materials, expected.glossy_materials);
  EXPECT_EQ(s.aperture, expected.aperture);
  for (size_t f = 0; f < static_cast<size_t>(SceneFeature::count); ++f)
    EXPECT_EQ(s.has(static_cast<SceneFeature>(f)), expected.has(static_cast<SceneFeature>(f))) << f;
}

TEST(DefaultWorld, HasGradedRowsASkyAndNoFiles) {
  SceneView v = make_scene_view(default_world(), 16.0f / 9.0f);
  EXPECT_TRUE(v.has_environment);
  EXPECT_TRUE(v.environment.path.empty());  // the procedural sky
  std::vector<float> roughness, metalness;
  for (const auto& m : v.materials) {
    if (m.name.rfind("roughness ", 0) == 0) roughness.push_back(m.roughness);
    if (m.name.rfind("metalness ", 0) == 0) metalness.push_back(m.metalness);
  }
  ASSERT_GE(roughness.size(), 5u);
  ASSERT_EQ(metalness.size(), roughness.size());
  EXPECT_EQ(roughness.front(), 0.0f);
  EXPECT_EQ(roughness.back(), 1.0f);
  EXPECT_EQ(metalness.front(), 0.0f);
  EXPECT_EQ(metalness.back(), 1.0f);
  for (size_t i = 1; i < roughness.size(); ++i) {
    EXPECT_GT(roughness[i], roughness[i - 1]);
    EXPECT_GT(metalness[i], metalness[i - 1]);
  }
  for (const auto& t : v.textures) EXPECT_FALSE(t->rgba8.empty());
}

TEST(DefaultWorld, MeshesAreWellFormedWithUnitNormals) {
  SceneView v = make_scene_view(default_world(), 16.0f / 9.0f);
  for (const auto& shared : v.meshes) {
    const MeshData& m = *shared;
    EXPECT_EQ(mesh_problem(m), "") << m.name;
    EXPECT_FALSE(m.indices.empty()) << m.name;
    for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << m.name;
  }
  for (const auto& d : v.draws) {
    ASSERT_GE(d.mesh, 0);
    ASSERT_LT(d.mesh, static_cast<int>(v.meshes.size()));
    ASSERT_GE(d.material, 0);
    ASSERT_LT(d.material, static_cast<int>(v.materials.size()));
  }
}

// Generated normals agree with the generators' analytic ones (outward, counter-clockwise
// winding): tolerance 0.05 in the dot product for the coarse tessellations used.
TEST(MeshGenerators, WindingAgreesWithNormals) {
  for (MeshData m : {make_sphere(1.0f), make_box({1, 2, 3}), make_quad(2, 1), make_capsule(1.0f, 0.3f), make_bunny()}) {
    ASSERT_EQ(mesh_problem(m), "") << m.name;
    MeshData generated = m;
    generate_normals(generated);
    size_t agree = 0;
    for (size_t i = 0; i < m.normals.size(); ++i) agree += glm::dot(m.normals[i], generated.normals[i]) > 0.95f;
    // Box edges and sphere poles share positions only within one face, so all must agree.
    EXPECT_GT(agree, m.normals.size() * 95 / 100) << m.name;
  }
}

// Every drawn object's centre and the light positions are on screen, in front of the camera.
TEST(DefaultWorld, CameraFramesTheObjectsAtSixteenByNine) {
  SceneView v = make_scene_view(default_world(), 16.0f / 9.0f);
  glm::mat4 vp = v.camera.projection * v.camera.view;
  auto on_screen = [&](glm::vec3 p) {
    glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return c.w > 0 && std::abs(c.x / c.w) < 0.95f && std::abs(c.y / c.w) < 0.95f && c.z / c.w > 0 && c.z / c.w <= 1;
  };
  for (const auto& d : v.draws) {
    Bounds b = transformed_bounds(v.mesh_of(d), d.world);
    bool is_room = v.materials[static_cast<size_t>(d.material)].name == "wall" ||
                   v.materials[static_cast<size_t>(d.material)].name == "floor";
    if (!is_room) {
      EXPECT_TRUE(on_screen(b.min)) << v.materials[static_cast<size_t>(d.material)].name;
      EXPECT_TRUE(on_screen(b.max)) << v.materials[static_cast<size_t>(d.material)].name;
    }
  }
  EXPECT_TRUE(on_screen(v.sphere_lights.at(0).center));
  EXPECT_TRUE(on_screen(v.tube_lights.at(0).end0));
  EXPECT_TRUE(on_screen(v.tube_lights.at(0).end1));
}

}  // namespace
}  // namespace lg
