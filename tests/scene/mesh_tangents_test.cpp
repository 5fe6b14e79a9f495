// generate_tangents(): the tangent frame glTF normal maps expect (tangent along +u, bitangent
// cross(n, t) * w toward decreasing v), mirrored uvs, degenerate uvs, and a whole sphere.
// Tolerance 1e-5: single-precision sums of a few unit vectors.
#include "runtime/scene/mesh_tangents.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "runtime/scene/mesh_generators.h"

namespace lg {
namespace {

// A unit square at z = 0 facing +Z with glTF's uvs: (0, 0) at the top-left corner.
MeshData square() {
  MeshData m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals.assign(4, {0, 0, 1});
  m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

void expect_near(glm::vec4 a, glm::vec4 b) {
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-5f) << "component " << c;
}

TEST(MeshTangents, TangentAlongUBitangentTowardDecreasingV) {
  MeshData m = square();
  generate_tangents(m, 0);
  ASSERT_EQ(m.tangents.size(), 4u);
  for (const auto& t : m.tangents) expect_near(t, {1, 0, 0, 1});  // bitangent cross(z, x) = +y: image "up"
}

TEST(MeshTangents, MirroredUvsFlipHandedness) {
  MeshData m = square();
  for (auto& uv : m.uvs) uv.x = 1.0f - uv.x;
  generate_tangents(m, 0);
  for (const auto& t : m.tangents) {
    expect_near(t, {-1, 0, 0, -1});
    // The bitangent the shader builds still points up the image.
    glm::vec3 b = glm::cross(glm::vec3(0, 0, 1), glm::vec3(t)) * t.w;
    EXPECT_NEAR(b.y, 1.0f, 1e-5f);
  }
}

TEST(MeshTangents, ReadsTheRequestedUvSet) {
  MeshData m = square();
  m.uvs1 = m.uvs;
  for (auto& uv : m.uvs1) uv = {uv.y, uv.x};  // set 1 runs u down the square
  generate_tangents(m, 1);
  for (const auto& t : m.tangents) expect_near(t, {0, -1, 0, -1});
}

TEST(MeshTangents, DegenerateOrMissingUvsGiveAPerpendicular) {
  MeshData m = square();
  m.uvs.assign(4, {0.5f, 0.5f});
  generate_tangents(m, 0);
  for (const auto& t : m.tangents) {
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(t), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    EXPECT_EQ(t.w, 1.0f);
  }
  m.tangents.clear();
  generate_tangents(m, 1);  // no set 1
  EXPECT_EQ(m.tangents.size(), 4u);
}

TEST(MeshTangents, SphereTangentsAreUnitAndOrthogonal) {
  MeshData m = make_sphere(1.0f, 24, 12);
  ASSERT_FALSE(m.uvs.empty());
  generate_tangents(m, 0);
  ASSERT_EQ(m.tangents.size(), m.positions.size());
  for (size_t i = 0; i < m.tangents.size(); ++i) {
    glm::vec3 t(m.tangents[i]);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << i;
    EXPECT_NEAR(glm::dot(t, m.normals[i]), 0.0f, 1e-5f) << i;
    EXPECT_TRUE(m.tangents[i].w == 1.0f || m.tangents[i].w == -1.0f) << i;
  }
}

}  // namespace
}  // namespace lg
