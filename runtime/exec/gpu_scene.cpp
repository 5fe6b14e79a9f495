#include "runtime/exec/gpu_scene.h"

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "runtime/exec/texture_mips.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"
#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {

void use_gpu_vertices(GraphicsPipelineDesc& desc, bool material_attributes) {
  desc.vertex_bindings = {{0, sizeof(GpuVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position)},
                            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal)},
                            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv)}};
  if (material_attributes)
    desc.vertex_attributes.insert(desc.vertex_attributes.end(),
                                  {{3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv1)},
                                   {4, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, tangent)},
                                   {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, color)}});
}

namespace {

VkFormat texture_format(ColorSpace color_space) {
  return color_space == ColorSpace::srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

void check_mesh(const MeshData& mesh) {
  const size_t count = mesh.positions.size();
  auto fail = [&](const std::string& what) { throw std::invalid_argument("mesh '" + mesh.name + "': " + what); };
  if (mesh.normals.size() != count)
    fail(std::to_string(mesh.normals.size()) + " normals for " + std::to_string(count) + " positions");
  auto check_optional = [&](size_t size, const char* what) {
    if (size != 0 && size != count)
      fail(std::to_string(size) + " " + what + " for " + std::to_string(count) + " positions");
  };
  check_optional(mesh.uvs.size(), "uvs");
  check_optional(mesh.uvs1.size(), "uvs of set 1");
  check_optional(mesh.colors.size(), "colours");
  check_optional(mesh.tangents.size(), "tangents");
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

GpuScene::GpuScene(Context& context) : context_(context), submitter_(context) {
  white_ = Image::dedicated(context_, {.name = "white texture", .format = texture_format(ColorSpace::srgb)});
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
    GpuVertex& out = vertices[v];
    for (int c = 0; c < 3; ++c) {
      out.position[c] = mesh.positions[v][c];
      out.normal[c] = mesh.normals[v][c];
    }
    for (int c = 0; c < 2; ++c) {
      out.uv[c] = mesh.uvs.empty() ? 0.0f : mesh.uvs[v][c];
      if (!mesh.uvs1.empty()) out.uv1[c] = mesh.uvs1[v][c];
    }
    for (int c = 0; c < 4; ++c) {
      if (!mesh.tangents.empty()) out.tangent[c] = mesh.tangents[v][c];
      if (!mesh.colors.empty()) out.color[c] = mesh.colors[v][c];
    }
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
  const VkFormat format = texture_format(texture.color_space);
  Image image = Image::dedicated(context_, {.name = texture.name,
                                            .format = format,
                                            .width = texture.width,
                                            .height = texture.height,
                                            .mips = mip_count(texture.width, texture.height)});
  // Decoding and re-encoding is exact for 8-bit values, so mip 0's bytes arrive unchanged; the
  // smaller mips are averaged in linear values (sRGB decoded first).
  std::vector<float> rgba(texels * 4);
  decode_texels(format_info(format), std::as_bytes(std::span(texture.rgba8)), rgba);
  const std::vector<std::vector<float>> levels = mip_chain(rgba, texture.width, texture.height);
  for (uint32_t mip = 0; mip < levels.size(); ++mip)
    upload_image(submitter_, image, levels[mip], VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, {.mip = mip},
                 mip == 0 ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  return image;
}

VkSampler GpuScene::sampler(const TextureSampling& sampling) {
  for (const auto& [key, made] : samplers_)
    if (key == sampling) return made->handle();
  auto address = [](TextureWrap wrap) {
    return wrap == TextureWrap::repeat            ? Address::repeat
           : wrap == TextureWrap::mirrored_repeat ? Address::mirrored_repeat
                                                  : Address::clamp;
  };
  auto filter = [](TextureFilter f) { return f == TextureFilter::linear ? Filter::linear : Filter::nearest; };
  // Anisotropy refines trilinear filtering only; 16 samples is the usual ceiling.
  SamplerDesc desc{
      .filter = filter(sampling.mag),
      .address = address(sampling.wrap_u),
      .min_filter = filter(sampling.min),
      .mip_filter = sampling.mip == MipFilter::nearest ? Filter::nearest : Filter::linear,
      .address_v = address(sampling.wrap_v),
      .mip_0_only = sampling.mip == MipFilter::none,
      .max_anisotropy = sampling.min == TextureFilter::linear && sampling.mip == MipFilter::linear ? 16.0f : 1.0f};
  samplers_.emplace_back(sampling, std::make_unique<Sampler>(context_, desc));
  return samplers_.back().second->handle();
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
  bounds_ = lg::mesh_bounds(scene);
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
