// make_scene_view(): camera matrices (Vulkan clip space, reversed Z, infinite far plane),
// world-space lights, previous-frame matrices, version and summary, and the assets a view shares
// with its world. Tolerances: 1e-5 relative on matrices and positions (float arithmetic of a few
// operations).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/projection.h"

namespace lg {
namespace {

glm::vec4 clip_of(const SceneView& v, glm::vec3 world_point) {
  return v.camera.projection * v.camera.view * glm::vec4(world_point, 1.0f);
}

World world_with_camera(glm::vec3 position, glm::vec3 target) {
  World w;
  Entity cam = w.create("camera");
  w.add<Transform>(cam, {position, look_rotation(target - position), glm::vec3(1.0f), {}});
  w.add<Camera>(cam, {glm::radians(60.0f), 0.1f, 0.0f, 5.0f});
  return w;
}

TEST(Projection, DepthIsNearOverDistanceAndReversed) {
  glm::mat4 p = reversed_z_infinite_perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f);
  for (float distance : {0.1f, 0.5f, 1.0f, 10.0f, 1e3f, 1e6f}) {
    glm::vec4 c = p * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
    float depth = c.z / c.w;
    EXPECT_NEAR(depth, 0.1f / distance, 1e-6f * (0.1f / distance) + 1e-9f);
    EXPECT_GT(depth, 0.0f);
    EXPECT_LE(depth, 1.0f + 1e-6f);
  }
  // Nearer is larger (reversed Z); the near plane is exactly 1.
  glm::vec4 near_point = p * glm::vec4(0, 0, -0.1f, 1), far_point = p * glm::vec4(0, 0, -50.0f, 1);
  EXPECT_NEAR(near_point.z / near_point.w, 1.0f, 1e-6f);
  EXPECT_GT(near_point.z / near_point.w, far_point.z / far_point.w);
  // A point behind the camera has w < 0 and is clipped.
  EXPECT_LT((p * glm::vec4(0, 0, 1.0f, 1)).w, 0.0f);
}

TEST(SceneView, PointInFrontLandsInClipDepthZeroToOneWithYDown) {
  World w = world_with_camera({0, 2, 5}, {0, 2, 0});
  SceneView v = make_scene_view(w, 16.0f / 9.0f);
  glm::vec4 ahead = clip_of(v, {0, 2, 0});
  EXPECT_GT(ahead.w, 0.0f);
  float depth = ahead.z / ahead.w;
  EXPECT_GT(depth, 0.0f);
  EXPECT_LE(depth, 1.0f);
  EXPECT_NEAR(depth, 0.1f / 5.0f, 1e-6f);
  EXPECT_NEAR(ahead.x / ahead.w, 0.0f, 1e-6f);
  // Above the view axis is the top of the screen: negative y in Vulkan's clip space.
  glm::vec4 above = clip_of(v, {0, 3, 0});
  EXPECT_LT(above.y / above.w, 0.0f);
  // To the right (+X seen from +Z looking at -Z) is positive x.
  glm::vec4 right = clip_of(v, {1, 2, 0});
  EXPECT_GT(right.x / right.w, 0.0f);
  // The top edge of the field of view maps to y = -1; the aspect ratio scales x.
  float half = std::tan(glm::radians(30.0f)) * 5.0f;
  EXPECT_NEAR(clip_of(v, {0, 2 + half, 0}).y / clip_of(v, {0, 2 + half, 0}).w, -1.0f, 1e-5f);
  float half_w = half * 16.0f / 9.0f;
  EXPECT_NEAR(clip_of(v, {half_w, 2, 0}).x / clip_of(v, {half_w, 2, 0}).w, 1.0f, 1e-5f);
  EXPECT_NEAR(v.camera.position.z, 5.0f, 1e-6f);
  EXPECT_FLOAT_EQ(v.camera.near_plane, 0.1f);
}

TEST(SceneView, CameraScaleDoesNotDistortTheView) {
  World w = world_with_camera({0, 0, 5}, {0, 0, 0});
  w.each<Camera, Transform>([](Entity, Camera&, Transform& t) { t.scale = glm::vec3(3.0f); });
  SceneView v = make_scene_view(w, 1.0f);
  glm::vec4 c = clip_of(v, {0, 0, 0});
  EXPECT_NEAR(c.z / c.w, 0.1f / 5.0f, 1e-6f);
}

TEST(SceneView, LightsAreInWorldSpace) {
  World w;
  Entity parent = w.create();
  w.add<Transform>(parent, {{10, 0, 0}, glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0)), glm::vec3(2.0f), {}});
  Entity tube = w.create(), rect = w.create(), sun = w.create(), sphere = w.create();
  w.add<Transform>(tube, {{0, 1, 0}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), parent});
  w.add<TubeLight>(tube, {{1, 1, 1}, 4.0f, 1.0f, 0.1f, true});
  w.add<Transform>(rect, {{0, 0, 0}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), parent});
  w.add<RectLight>(rect, {{0.5f, 1, 1}, 2.0f, 1.0f, 0.5f, true, true});
  w.add<Transform>(sun, {{0, 0, 0}, look_rotation({0, -1, 0}), glm::vec3(1.0f), {}});
  w.add<DirectionalLight>(sun, {{1, 1, 1}, 3.0f, 0.01f, false});
  w.add<Transform>(sphere, {{0, 0, 0}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), parent});
  w.add<SphereLight>(sphere, {{1, 0, 0}, 5.0f, 0.25f, true});
  SceneView v = make_scene_view(w, 1.0f);
  ASSERT_EQ(v.tube_lights.size(), 1u);
  // The tube lies along the parent's local X, which the 90 degree turn about Y maps to -Z.
  const auto& t = v.tube_lights[0];
  EXPECT_NEAR(t.end0.x, 10.0f, 1e-5f);
  EXPECT_NEAR(t.end0.y, 2.0f, 1e-5f);
  EXPECT_NEAR(t.end0.z, 1.0f, 1e-5f);
  EXPECT_NEAR(t.end1.z, -1.0f, 1e-5f);
  EXPECT_NEAR(t.radius, 0.2f, 1e-6f);
  EXPECT_FLOAT_EQ(t.radiance.x, 4.0f);
  ASSERT_EQ(v.rect_lights.size(), 1u);
  EXPECT_NEAR(v.rect_lights[0].half_x.z, -1.0f, 1e-5f);  // width 1 scaled by 2, halved
  EXPECT_NEAR(v.rect_lights[0].half_y.y, -0.5f, 1e-5f);
  // It emits down its local -Z, which the parent's turn makes world -X.
  glm::vec3 facing = glm::cross(v.rect_lights[0].half_x, v.rect_lights[0].half_y);
  EXPECT_LT(facing.x, 0.0f);
  EXPECT_TRUE(v.rect_lights[0].two_sided);
  EXPECT_FLOAT_EQ(v.rect_lights[0].radiance.x, 1.0f);
  ASSERT_EQ(v.directional_lights.size(), 1u);
  EXPECT_NEAR(v.directional_lights[0].direction.y, -1.0f, 1e-5f);
  EXPECT_FALSE(v.directional_lights[0].casts_shadows);
  ASSERT_EQ(v.sphere_lights.size(), 1u);
  EXPECT_NEAR(v.sphere_lights[0].radius, 0.5f, 1e-6f);
  EXPECT_NEAR(v.sphere_lights[0].center.x, 10.0f, 1e-5f);
}

TEST(SceneView, PreviousFrameMatricesComeFromThePreviousView) {
  World w = world_with_camera({0, 0, 5}, {0, 0, 0});
  Entity box = w.create();
  w.add<Transform>(box, {{0, 0, 0}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f), {}});
  w.add<MeshRenderer>(box, {w.add_mesh({}), -1});
  SceneView first = make_scene_view(w, 1.0f);
  ASSERT_EQ(first.draws.size(), 1u);
  EXPECT_EQ(first.draws[0].previous_world, first.draws[0].world);
  EXPECT_EQ(first.camera.previous_view_projection, first.camera.projection * first.camera.view);

  w.get<Transform>(box).position = {1, 0, 0};
  w.each<Camera, Transform>([](Entity, Camera&, Transform& t) { t.position.x = 0.5f; });
  Entity added = w.create();  // a new draw has no history: previous equals current
  w.add<MeshRenderer>(added, {0, -1});
  SceneView second = make_scene_view(w, 1.0f, &first);
  ASSERT_EQ(second.draws.size(), 2u);
  EXPECT_EQ(second.draws[0].previous_world, first.draws[0].world);
  EXPECT_NE(second.draws[0].world, first.draws[0].world);
  EXPECT_EQ(second.draws[1].previous_world, second.draws[1].world);
  EXPECT_EQ(second.camera.previous_view_projection, first.camera.projection * first.camera.view);
  EXPECT_NE(second.camera.view, first.camera.view);
}

TEST(SceneView, RejectsABadAspectRatio) {
  World w;
  EXPECT_THROW(make_scene_view(w, 0.0f), std::invalid_argument);
  EXPECT_THROW(make_scene_view(w, std::nanf("")), std::invalid_argument);
}

TEST(SceneView, VersionFollowsAssetChanges) {
  World w;
  w.add_mesh({});
  uint64_t v1 = make_scene_view(w, 1.0f).version;
  EXPECT_EQ(make_scene_view(w, 1.0f).version, v1);  // nothing changed
  w.edit_mesh(0).name = "changed";
  EXPECT_NE(make_scene_view(w, 1.0f).version, v1);
}

// A view holds the world's own meshes and textures (no copy per frame); an edit of the world
// copies what a view or another world still holds, so each keeps what it saw.
TEST(SceneView, SharesTheWorldsAssetsAndKeepsWhatItSaw) {
  World w;
  Entity e = w.create("box");
  w.add<MeshRenderer>(e, {w.add_mesh(make_box(glm::vec3(1.0f))), -1});
  w.add_texture({"texels", 1, 1, {1, 2, 3, 4}});
  SceneView first = make_scene_view(w, 1.0f);
  SceneView second = make_scene_view(w, 1.0f, &first);
  for (const SceneView* v : {&first, &second}) {
    EXPECT_EQ(v->meshes.at(0).get(), w.meshes()[0].get());
    EXPECT_EQ(v->textures.at(0).get(), w.textures()[0].get());
  }
  const MeshData* seen = w.meshes()[0].get();
  const size_t seen_vertices = seen->positions.size();
  uint64_t seen_version = second.version;

  w.edit_mesh(0).positions.push_back(glm::vec3(9.0f));
  w.edit_texture(0).rgba8[0] = 200;
  EXPECT_EQ(first.meshes[0].get(), seen);  // the views keep the mesh they were made with
  EXPECT_EQ(second.mesh_of(second.draws[0]).positions.size(), seen_vertices);
  EXPECT_EQ(second.textures[0]->rgba8[0], 1);
  SceneView third = make_scene_view(w, 1.0f, &second);
  EXPECT_EQ(third.mesh_of(third.draws[0]).positions.size(), seen_vertices + 1);
  EXPECT_EQ(third.textures[0]->rgba8[0], 200);
  EXPECT_NE(third.version, seen_version);

  // Without views holding it, an edit changes the mesh in place.
  first = {};
  second = {};
  third = {};
  const MeshData* alone = w.meshes()[0].get();
  w.edit_mesh(0).name = "edited";
  EXPECT_EQ(w.meshes()[0].get(), alone);

  // A copy of the world shares the assets until one of the two edits them.
  World copy = w;
  copy.edit_mesh(0).name = "copy";
  EXPECT_EQ(w.meshes()[0]->name, "edited");
  EXPECT_EQ(copy.meshes()[0]->name, "copy");
}

TEST(SceneView, OutlivesItsWorld) {
  SceneView v;
  {
    World w;
    Entity e = w.create("box");
    w.add<MeshRenderer>(e, {w.add_mesh(make_box(glm::vec3(2.0f))), -1});
    v = make_scene_view(w, 1.0f);
  }
  ASSERT_EQ(v.draws.size(), 1u);
  EXPECT_EQ(v.mesh_of(v.draws[0]).positions, make_box(glm::vec3(2.0f)).positions);
}

TEST(SceneView, MeshOfRefusesAMissingOrNullMesh) {
  SceneView v;
  v.meshes.push_back(nullptr);
  DrawItem draw;
  draw.mesh = 0;
  EXPECT_THROW(v.mesh_of(draw), std::invalid_argument);
  draw.mesh = 1;
  EXPECT_THROW(v.mesh_of(draw), std::invalid_argument);
  draw.mesh = -1;
  EXPECT_THROW(v.mesh_of(draw), std::invalid_argument);
  // A host's own mesh, not owned by the view (shared_ptr's aliasing constructor).
  const MeshData host_mesh = make_box(glm::vec3(1.0f));
  v.meshes[0] = std::shared_ptr<const MeshData>(std::shared_ptr<void>(), &host_mesh);
  draw.mesh = 0;
  EXPECT_EQ(&v.mesh_of(draw), &host_mesh);
}

TEST(SceneView, SummaryCountsWhatTheWorldHas) {
  World w = world_with_camera({0, 0, 5}, {0, 0, 0});
  w.each<Camera>([](Entity, Camera& c) {
    c.aperture = 0.02f;
    c.focus_distance = 3.0f;
  });
  PbrMaterial material;
  material.roughness = 0.95f;
  int matte = w.add_material(material);
  Entity e = w.create();
  w.add<MeshRenderer>(e, {w.add_mesh({}), matte});
  w.add<PointLight>(w.create());
  w.add<RectLight>(w.create());
  w.add<RectLight>(w.create());
  w.add<IrradianceVolume>(w.create());
  w.add<ReflectionProbe>(w.create());
  SceneSummary s = make_scene_view(w, 1.0f).summary();
  EXPECT_EQ(s.directional_lights, 0);
  EXPECT_EQ(s.point_lights, 1);
  EXPECT_EQ(s.sphere_lights, 0);
  EXPECT_EQ(s.tube_lights, 0);
  EXPECT_EQ(s.rectangle_lights, 2);
  EXPECT_FALSE(s.shadows);
  EXPECT_FALSE(s.environment);
  EXPECT_EQ(s.irradiance_volumes, 1);
  EXPECT_EQ(s.reflection_probes, 1);
  EXPECT_FALSE(s.glossy_materials);  // roughness 0.95, not metal
  EXPECT_NEAR(s.aperture, 0.02, 1e-7);
  EXPECT_NEAR(s.focus_distance, 3.0, 1e-6);
  EXPECT_TRUE(s.has(SceneFeature::thin_lens_camera));
  w.edit_material(matte).metalness = 0.1f;
  EXPECT_TRUE(make_scene_view(w, 1.0f).summary().glossy_materials);
  material.roughness = 0.85f;
  w.edit_material(matte) = material;
  EXPECT_TRUE(make_scene_view(w, 1.0f).summary().glossy_materials);
  // Rough factors, but a metallic-roughness texture may lower the roughness anywhere.
  material.roughness = 1.0f;
  material.metallic_roughness_texture.texture = 0;
  w.edit_material(matte) = material;
  EXPECT_TRUE(make_scene_view(w, 1.0f).summary().glossy_materials);
}

}  // namespace
}  // namespace lg
