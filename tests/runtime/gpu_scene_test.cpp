// GpuScene: meshes and textures uploaded from a SceneView and read back byte for byte;
// uploads happen again only when the scene's version changes; malformed meshes are refused
// with their names.
#include "runtime/exec/gpu_scene.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>

#include "runtime/gpu/format.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"
#include "runtime/scene/scene_view.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using GpuSceneTest = GpuTest;

// Slot `index` of the view's meshes replaced by a copy that the test may change.
MeshData& edited_mesh(SceneView& scene, size_t index) {
  auto copy = std::make_shared<MeshData>(*scene.meshes.at(index));
  scene.meshes[index] = copy;
  return *copy;
}

SceneView one_triangle_scene() {
  SceneView scene;
  scene.version = 7;
  MeshData mesh;
  mesh.name = "triangle";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(std::make_shared<const MeshData>(std::move(mesh)));
  MeshData quad;
  quad.name = "quad";
  quad.positions = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
  quad.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(std::make_shared<const MeshData>(std::move(quad)));
  TextureData texture;
  texture.name = "checker";
  texture.width = 3;
  texture.height = 2;
  texture.rgba8 = {0,   1,   2,   255, 17,  34,  51,  68, 128, 129, 130, 131,
                   200, 201, 202, 203, 254, 253, 252, 0,  9,   99,  199, 255};
  scene.textures.push_back(std::make_shared<const TextureData>(std::move(texture)));
  return scene;
}

TEST_F(GpuSceneTest, UploadsInterleavedVerticesAndIndices) {
  const SceneView scene = one_triangle_scene();
  GpuScene gpu(context(), submitter());
  gpu.update(scene);
  ASSERT_EQ(gpu.mesh_count(), 2);
  for (int m = 0; m < 2; ++m) {
    const MeshData& want = *scene.meshes[m];
    const GpuMesh& mesh = gpu.mesh(m);
    EXPECT_EQ(mesh.vertex_count, want.positions.size());
    EXPECT_EQ(mesh.index_count, want.indices.size());
    std::vector<std::byte> bytes = read_buffer(submitter(), mesh.vertices);
    ASSERT_EQ(bytes.size(), want.positions.size() * sizeof(GpuVertex));
    std::vector<GpuVertex> vertices(want.positions.size());
    std::memcpy(vertices.data(), bytes.data(), bytes.size());
    for (size_t v = 0; v < vertices.size(); ++v) {
      const glm::vec2 uv = want.uvs.empty() ? glm::vec2(0) : want.uvs[v];
      const float expected[8] = {want.positions[v].x,
                                 want.positions[v].y,
                                 want.positions[v].z,
                                 want.normals[v].x,
                                 want.normals[v].y,
                                 want.normals[v].z,
                                 uv.x,
                                 uv.y};
      EXPECT_EQ(std::memcmp(&vertices[v], expected, sizeof expected), 0) << want.name << " vertex " << v;
    }
    std::vector<std::byte> indices = read_buffer(submitter(), mesh.indices);
    ASSERT_EQ(indices.size(), want.indices.size() * 4);
    EXPECT_EQ(std::memcmp(indices.data(), want.indices.data(), indices.size()), 0) << want.name;
  }
}

TEST_F(GpuSceneTest, UploadsTexturesInSrgbAndAWhiteTexture) {
  const SceneView scene = one_triangle_scene();
  GpuScene gpu(context(), submitter());
  gpu.update(scene);
  ASSERT_EQ(gpu.texture_count(), 1);
  const Image& texture = gpu.texture(0);
  EXPECT_EQ(texture.desc().format, VK_FORMAT_R8G8B8A8_SRGB);
  std::vector<float> want(6 * 4);
  decode_texels(format_info(VK_FORMAT_R8G8B8A8_SRGB), std::as_bytes(std::span(scene.textures[0]->rgba8)), want);
  EXPECT_EQ(read_image(submitter(), texture, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL), want);
  EXPECT_EQ(read_image(submitter(), gpu.white_texture(), VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL),
            (std::vector<float>{1, 1, 1, 1}));
  EXPECT_EQ(&gpu.texture(-1), &gpu.white_texture());
}

TEST_F(GpuSceneTest, UploadsAgainOnlyWhenTheVersionChanges) {
  SceneView scene = one_triangle_scene();
  GpuScene gpu(context(), submitter());
  gpu.update(scene);
  scene.meshes.pop_back();
  gpu.update(scene);  // same version: the scene is taken as unchanged
  EXPECT_EQ(gpu.mesh_count(), 2);
  scene.version = 8;
  gpu.update(scene);
  EXPECT_EQ(gpu.mesh_count(), 1);
}

TEST_F(GpuSceneTest, RefusesMalformedMeshesAndKeepsThePreviousUpload) {
  SceneView scene = one_triangle_scene();
  GpuScene gpu(context(), submitter());
  gpu.update(scene);
  scene.version = 9;
  edited_mesh(scene, 1).indices.push_back(4);
  try {
    gpu.update(scene);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "mesh 'quad': 7 indices, not three per triangle");
  }
  edited_mesh(scene, 1).indices = {0, 1, 4};
  EXPECT_THROW(gpu.update(scene), std::invalid_argument);
  EXPECT_EQ(gpu.mesh_count(), 2);
  EXPECT_EQ(gpu.mesh(1).index_count, 6u);
}

}  // namespace
}  // namespace lg::test
