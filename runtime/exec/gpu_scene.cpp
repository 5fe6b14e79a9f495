#include "runtime/exec/gpu_scene.h"

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "runtime/gpu/format.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"
#include "runtime/scene/scene_view.h"

namespace lg {

void use_gpu_vertices(GraphicsPipelineDesc& desc) {
  desc.vertex_bindings = {{0, sizeof(GpuVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position)},
                            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal)},
                            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv)}};
}
namespace {

constexpr VkFormat texture_format = VK_FORMAT_R8G8B8A8_SRGB;

void check_mesh(const MeshData& mesh) {
  const size_t count = mesh.positions.size();
  auto fail = [&](const std::string& what) { throw std::invalid_argument("mesh '" + mesh.name + "': " + what); };
  if (mesh.normals.size() != count)
    fail(std::to_string(mesh.normals.size()) + " normals for " + std::to_string(count) + " positions");
  if (!mesh.uvs.empty() && mesh.uvs.size() != count)
    fail(std::to_string(mesh.uvs.size()) + " uvs for " + std::to_string(count) + " positions");
  if (mesh.indices.size() % 3 != 0) fail(std::to_string(mesh.indices.size()) + " indices, not three per triangle");
  for (uint32_t i : mesh.indices)
    if (i >= count) fail("index " + std::to_string(i) + " past the last of " + std::to_string(count) + " vertices");
}

template <class T>
const std::shared_ptr<const T>& not_null(const std::shared_ptr<const T>& asset, const char* what, size_t index) {
  if (!asset) throw std::invalid_argument(std::string(what) + " " + std::to_string(index) + " of the scene is null");
  return asset;
}

}  // namespace

GpuScene::GpuScene(Context& context, Submitter& submitter) : context_(context), submitter_(submitter) {
  white_ = Image::dedicated(context_, {.name = "white texture", .format = texture_format});
  const float white[4] = {1, 1, 1, 1};
  upload_image(submitter_, white_, white, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}

GpuMesh GpuScene::upload(const MeshData& mesh) {
  check_mesh(mesh);
  GpuMesh out;
  out.vertex_count = static_cast<uint32_t>(mesh.positions.size());
  out.index_count = static_cast<uint32_t>(mesh.indices.size());
  if (out.vertex_count == 0) return out;
  std::vector<GpuVertex> vertices(out.vertex_count);
  for (size_t v = 0; v < vertices.size(); ++v) {
    const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v];
    vertices[v] = {{mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z},
                   {mesh.normals[v].x, mesh.normals[v].y, mesh.normals[v].z},
                   {uv.x, uv.y}};
  }
  out.vertices = Buffer::dedicated(context_, {"vertices of '" + mesh.name + "'", vertices.size() * sizeof(GpuVertex),
                                              default_buffer_usage | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT});
  upload_buffer(submitter_, out.vertices, std::as_bytes(std::span(vertices)));
  if (out.index_count > 0) {
    out.indices = Buffer::dedicated(context_, {"indices of '" + mesh.name + "'", mesh.indices.size() * sizeof(uint32_t),
                                               default_buffer_usage | VK_BUFFER_USAGE_INDEX_BUFFER_BIT});
    upload_buffer(submitter_, out.indices, std::as_bytes(std::span(mesh.indices)));
  }
  return out;
}

Image GpuScene::upload(const TextureData& texture) {
  const uint64_t texels = uint64_t{texture.width} * texture.height;
  if (texels == 0 || texture.rgba8.size() != texels * 4)
    throw std::invalid_argument("texture '" + texture.name + "': " + std::to_string(texture.rgba8.size()) +
                                " bytes for " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
                                " RGBA8 texels");
  Image image = Image::dedicated(
      context_, {.name = texture.name, .format = texture_format, .width = texture.width, .height = texture.height});
  // Decoding and re-encoding sRGB is exact for 8-bit values, so the bytes arrive unchanged.
  std::vector<float> rgba(texels * 4);
  decode_texels(format_info(texture_format), std::as_bytes(std::span(texture.rgba8)), rgba);
  upload_image(submitter_, image, rgba, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  return image;
}

void GpuScene::update(const SceneView& scene) {
  if (version_ == scene.version) return;
  // Built aside, so that a malformed mesh leaves the previous upload in place.
  std::vector<GpuMesh> meshes;
  meshes.reserve(scene.meshes.size());
  for (size_t i = 0; i < scene.meshes.size(); ++i) meshes.push_back(upload(*not_null(scene.meshes[i], "mesh", i)));
  std::vector<Image> textures;
  textures.reserve(scene.textures.size());
  for (size_t i = 0; i < scene.textures.size(); ++i)
    textures.push_back(upload(*not_null(scene.textures[i], "texture", i)));
  meshes_ = std::move(meshes);
  textures_ = std::move(textures);
  version_ = scene.version;
}

void draw_mesh(VkCommandBuffer cmd, const GpuMesh& mesh) {
  if (mesh.index_count == 0) return;
  const VkDeviceSize offset = 0;
  const VkBuffer vertices = mesh.vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdBindIndexBuffer(cmd, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, mesh.index_count, 1, 0, 0, 0);
}

}  // namespace lg
