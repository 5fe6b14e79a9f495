// GpuScene: meshes and textures uploaded from a SceneView and read back byte for byte (the
// material attributes and their defaults too); textures in their colour space's format with a
// full mip chain averaged in linear values; one sampler per distinct sampling; uploads happen
// again only when the scene's version changes; malformed meshes are refused with their names.
#include "runtime/exec/gpu_scene.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>

#include "runtime/exec/texture_mips.h"
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
  quad.uvs1 = {{0.5f, 0}, {1, 0.5f}, {0.5f, 1}, {0, 0.5f}};
  quad.tangents.assign(4, {1, 0, 0, -1});
  quad.colors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 0.5f}};
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
  GpuScene gpu(context());
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
      const glm::vec2 uv1 = want.uvs1.empty() ? glm::vec2(0) : want.uvs1[v];
      const glm::vec4 tangent = want.tangents.empty() ? glm::vec4(0) : want.tangents[v];
      const glm::vec4 color = want.colors.empty() ? glm::vec4(1) : want.colors[v];
      const float expected[18] = {want.positions[v].x,
                                  want.positions[v].y,
                                  want.positions[v].z,
                                  want.normals[v].x,
                                  want.normals[v].y,
                                  want.normals[v].z,
                                  uv.x,
                                  uv.y,
                                  uv1.x,
                                  uv1.y,
                                  tangent.x,
                                  tangent.y,
                                  tangent.z,
                                  tangent.w,
                                  color.r,
                                  color.g,
                                  color.b,
                                  color.a};
      static_assert(sizeof expected == sizeof(GpuVertex));
      EXPECT_EQ(std::memcmp(&vertices[v], expected, sizeof expected), 0) << want.name << " vertex " << v;
    }
    std::vector<std::byte> indices = read_buffer(submitter(), mesh.indices);
    ASSERT_EQ(indices.size(), want.indices.size() * 4);
    EXPECT_EQ(std::memcmp(indices.data(), want.indices.data(), indices.size()), 0) << want.name;
  }
}

TEST_F(GpuSceneTest, UploadsTexturesInSrgbAndAWhiteTexture) {
  const SceneView scene = one_triangle_scene();
  GpuScene gpu(context());
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

// A 3x2 texture has mips 3x2 and 1x1; the 1x1 is the mean of all six texels, sRGB decoded
// first for colour and as stored for data (UNORM). Read back through 8-bit encoding: 1/255.
TEST_F(GpuSceneTest, TexturesGetFullMipChainsInTheirColourSpacesFormat) {
  SceneView scene = one_triangle_scene();
  TextureData data = *scene.textures[0];
  data.color_space = ColorSpace::linear;
  scene.textures.push_back(std::make_shared<const TextureData>(data));
  GpuScene gpu(context());
  gpu.update(scene);
  for (int t = 0; t < 2; ++t) {
    const Image& texture = gpu.texture(t);
    const VkFormat format = t == 0 ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    EXPECT_EQ(texture.desc().format, format);
    ASSERT_EQ(texture.desc().mips, 2u);
    std::vector<float> texels(6 * 4);
    decode_texels(format_info(format), std::as_bytes(std::span(scene.textures[0]->rgba8)), texels);
    EXPECT_EQ(read_image(submitter(), texture, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL), texels);
    const std::vector<float> top = read_image(submitter(), texture, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, {.mip = 1});
    ASSERT_EQ(top.size(), 4u);
    for (int c = 0; c < 4; ++c) {
      float mean = 0;
      for (int i = 0; i < 6; ++i) mean += texels[size_t(i * 4 + c)] / 6.0f;
      EXPECT_NEAR(top[size_t(c)], mean, 1.0f / 255.0f) << "texture " << t << " channel " << c;
    }
  }
}

// Sizes that halve unevenly: every source texel counts in the level below (a plain 2x2 box
// would drop the third column of a 3-wide image). Exact: sums of small integers.
TEST(TextureMips, OddSizesAverageEveryTexel) {
  EXPECT_EQ(mip_count(1, 1), 1u);
  EXPECT_EQ(mip_count(5, 3), 3u);
  EXPECT_EQ(mip_count(1024, 1), 11u);
  const std::vector<float> row = {0, 0, 0, 0, 3, 3, 3, 3, 6, 6, 6, 6};  // 3x1
  auto levels = mip_chain(row, 3, 1);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0], row);
  EXPECT_EQ(levels[1], (std::vector<float>{3, 3, 3, 3}));
  levels = mip_chain(std::vector<float>(5 * 3 * 4, 0.25f), 5, 3);  // 5x3, 2x1, 1x1
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[1], std::vector<float>(2 * 4, 0.25f));
  EXPECT_EQ(levels[2], std::vector<float>(4, 0.25f));
}

TEST_F(GpuSceneTest, OneSamplerPerDistinctSampling) {
  GpuScene gpu(context());
  TextureSampling clamped{.wrap_u = TextureWrap::clamp_to_edge, .wrap_v = TextureWrap::mirrored_repeat};
  TextureSampling nearest{.mag = TextureFilter::nearest, .min = TextureFilter::nearest, .mip = MipFilter::none};
  VkSampler a = gpu.sampler({}), b = gpu.sampler(clamped), c = gpu.sampler(nearest);
  EXPECT_NE(a, b);
  EXPECT_NE(b, c);
  EXPECT_NE(a, c);
  EXPECT_EQ(gpu.sampler(clamped), b);
  EXPECT_EQ(gpu.sampler({}), a);
}

TEST_F(GpuSceneTest, UploadsAgainOnlyWhenTheVersionChanges) {
  SceneView scene = one_triangle_scene();
  GpuScene gpu(context());
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
  GpuScene gpu(context());
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
