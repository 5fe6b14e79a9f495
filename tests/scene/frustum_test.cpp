// Frustum culling (runtime/scene/frustum.h): boxes and spheres inside, outside, straddling a
// plane, behind the camera, and a huge box around the camera, for a reversed-Z infinite
// perspective camera and a reversed-Z orthographic one; transformed boxes; which draws stay.
// The cases sit a metre or more from the planes, so no tolerance is involved.
#include "runtime/scene/frustum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/projection.h"

namespace lg {
namespace {

Bounds box(glm::vec3 center, float half) {
  Bounds b;
  b.add(center - glm::vec3(half));
  b.add(center + glm::vec3(half));
  return b;
}

// At the origin looking down -Z, 90 degrees vertically and horizontally, near plane 0.1.
Frustum perspective() {
  return view_frustum(reversed_z_infinite_perspective(glm::radians(90.0f), 1.0f, 0.1f));
}

// Looking down -Z from z = 0: x and y in [-2, 2], depth 1 at distance 0 falling to 0 at 10.
Frustum orthographic() {
  glm::mat4 m(1.0f);
  m[0][0] = 0.5f;
  m[1][1] = -0.5f;
  m[2][2] = 0.1f;  // z = 1 + view z / 10 (view z is negative in front)
  m[3][2] = 1.0f;
  return view_frustum(m);
}

TEST(Frustum, PerspectiveKeepsWhatItSees) {
  const Frustum f = perspective();
  EXPECT_TRUE(touches(f, box({0, 0, -5}, 0.5f)));        // in front
  EXPECT_TRUE(touches(f, box({0, 0, -1e6f}, 1.0f)));     // far away: no far plane
  EXPECT_TRUE(touches(f, box({5, 0, -5}, 0.5f)));        // straddling the right plane x = -z
  EXPECT_TRUE(touches(f, box({0, 0, 0}, 1e4f)));         // a huge box around the camera
  EXPECT_FALSE(touches(f, box({8, 0, -5}, 0.5f)));       // beside the right plane
  EXPECT_FALSE(touches(f, box({-8, 0, -5}, 0.5f)));      // left
  EXPECT_FALSE(touches(f, box({0, 8, -5}, 0.5f)));       // above
  EXPECT_FALSE(touches(f, box({0, -8, -5}, 0.5f)));      // below
  EXPECT_FALSE(touches(f, box({0, 0, 5}, 0.5f)));        // behind the camera
  EXPECT_FALSE(touches(f, box({0, 0, -0.04f}, 0.02f)));  // between the eye and the near plane
  EXPECT_FALSE(touches(f, Bounds{}));                    // empty
}

TEST(Frustum, OrthographicHasAFarPlane) {
  const Frustum f = orthographic();
  EXPECT_TRUE(touches(f, box({0, 0, -5}, 0.5f)));
  EXPECT_TRUE(touches(f, box({0, 0, -10}, 0.5f)));   // straddling the far plane
  EXPECT_TRUE(touches(f, box({2, 2, -5}, 0.5f)));    // straddling a corner
  EXPECT_TRUE(touches(f, box({0, 0, 0}, 100.0f)));   // containing it all
  EXPECT_FALSE(touches(f, box({0, 0, -12}, 0.5f)));  // beyond the far plane
  EXPECT_FALSE(touches(f, box({0, 0, 2}, 0.5f)));    // behind
  EXPECT_FALSE(touches(f, box({3, 0, -5}, 0.5f)));   // beside: an orthographic side does not widen
  EXPECT_FALSE(touches(f, box({0, -3, -5}, 0.5f)));
}

TEST(Frustum, SpheresAreCulledOnlyWhenWhollyOutside) {
  const Frustum f = perspective();
  EXPECT_TRUE(touches(f, {0, 0, -5}, 0.1f));
  EXPECT_TRUE(touches(f, {8, 0, -5}, 3.0f));   // 3 / sqrt(2) = 2.1 m from the plane x = -z, radius 3
  EXPECT_FALSE(touches(f, {8, 0, -5}, 2.0f));  // radius 2 falls short of it
  EXPECT_TRUE(touches(f, {0, 0, 3}, 3.5f));    // behind the camera, reaching past the near plane
  EXPECT_FALSE(touches(f, {0, 0, 3}, 2.5f));
  EXPECT_TRUE(touches(f, {0, 0, 1e3f}, INFINITY));  // no range: reaches everything
}

TEST(Frustum, TransformedBoxHoldsTheTransformedCorners) {
  const Bounds unit = box({0, 0, 0}, 1.0f);
  const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1.0f), {10, 0, 0}), glm::radians(45.0f), {0, 1, 0});
  const Bounds b = transform_bounds(unit, m);
  // A unit cube turned 45 degrees about y spans sqrt(2) each way in x and z.
  EXPECT_NEAR(b.min.x, 10.0f - std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(b.max.z, std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(b.max.y, 1.0f, 1e-6f);
  EXPECT_TRUE(transform_bounds(Bounds{}, m).empty());
}

TEST(Frustum, VisibleDrawsLeaveOutTheDrawsOutsideTheView) {
  SceneView scene;
  scene.meshes = {std::make_shared<const MeshData>(make_box({1, 1, 1}))};
  for (glm::vec3 p : {glm::vec3(0, 0, -5), glm::vec3(0, 0, 5), glm::vec3(5, 0, -5), glm::vec3(20, 0, -5)})
    scene.draws.push_back({.mesh = 0, .world = glm::translate(glm::mat4(1.0f), p)});
  scene.draws.push_back({.mesh = 3});  // a bad index is kept for the draw to report
  const std::vector<Bounds> meshes = mesh_bounds(scene);
  EXPECT_EQ(visible_draws(scene, meshes, perspective()), (std::vector<uint32_t>{0, 2, 4}));
}

}  // namespace
}  // namespace lg
