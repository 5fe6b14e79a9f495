// mesh_plane(): the plane a flat mesh lies in, which side it faces, and how far from flat a
// mesh may be.
#include "runtime/scene/mesh_plane.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "runtime/scene/mesh_generators.h"

namespace lg {
namespace {

TEST(MeshPlane, QuadFacesUpThroughItsCentre) {
  MeshData quad = make_quad(4, 2);
  for (glm::vec3& p : quad.positions) p.y += 0.5f;
  const std::optional<MeshPlane> plane = mesh_plane(quad);
  ASSERT_TRUE(plane);
  EXPECT_TRUE(plane->flat());
  EXPECT_NEAR(glm::distance(glm::vec3(plane->plane), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(plane->plane.w, -0.5f, 1e-6f);
  EXPECT_EQ(plane->max_distance, 0.0);
}

TEST(MeshPlane, BentOrTwoFacedMeshesAreNotFlat) {
  MeshData bent = make_quad(4, 4);
  bent.positions[0].y += 0.01f;  // 1 cm on a 5.7 m diagonal: over the 1e-4 allowed
  const std::optional<MeshPlane> plane = mesh_plane(bent);
  ASSERT_TRUE(plane);
  EXPECT_FALSE(plane->flat());
  EXPECT_GT(plane->max_distance, 0.003);  // the plane fitted between the raised corner and the rest
  EXPECT_NEAR(plane->allowed_distance, 1e-4 * std::sqrt(32.0), 1e-7);

  MeshData two_faced = make_quad(1, 1);  // the same quad again, wound the other way
  const size_t triangles = two_faced.indices.size();
  for (size_t t = 0; t < triangles; t += 3)
    two_faced.indices.insert(two_faced.indices.end(),
                             {two_faced.indices[t], two_faced.indices[t + 2], two_faced.indices[t + 1]});
  EXPECT_FALSE(mesh_plane(two_faced));
  EXPECT_FALSE(mesh_plane(MeshData{}));  // no triangle
}

TEST(MeshPlane, TransformedPlaneKeepsAUnitNormal) {
  const glm::vec4 floor(0, 1, 0, -0.5f);  // y = 0.5
  const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0, 2, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(3));
  const glm::vec4 moved = transform_plane(floor, m);  // y = 0.5 * 3 + 2
  EXPECT_NEAR(glm::distance(glm::vec3(moved), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(moved.w, -3.5f, 1e-5f);
}

}  // namespace
}  // namespace lg
