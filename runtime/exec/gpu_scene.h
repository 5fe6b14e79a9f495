// The scene's meshes and textures on the device, for the kernels that draw or sample them:
// per mesh an interleaved vertex buffer (GpuVertex) and a uint32 index buffer, per texture an
// RGBA8 image with its full mip chain in READ_ONLY_OPTIMAL (sRGB for colour textures, UNORM for
// data), a 1x1 white texture for materials without one, and one sampler per distinct
// TextureSampling the materials use (anisotropic where the device allows it), and per mesh
// its box in its own space for frustum culling (runtime/scene/frustum.h).
// update() uploads again only when SceneView::version changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/submit.h"
#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/scene_view.h"

namespace lg {

class Context;
struct GraphicsPipelineDesc;

// One vertex as the vertex buffers hold it. What a mesh lacks is filled in: uvs 0, colour
// white, tangent 0 (the G-buffer then takes its frame from screen-space derivatives).
struct GpuVertex {
  float position[3];
  float normal[3];
  float uv[2];
  float uv1[2] = {};
  float tangent[4] = {};
  float color[4] = {1, 1, 1, 1};
};
static_assert(sizeof(GpuVertex) == 72);

// Sets a pipeline's vertex input to GpuVertex buffers: position, normal and uv at locations 0,
// 1 and 2 of binding 0, and with `material_attributes` also uv1, tangent and colour at 3, 4
// and 5 (a vertex shader is given only what it reads).
void use_gpu_vertices(GraphicsPipelineDesc& desc, bool material_attributes = false);

// A mesh without vertices has no buffers (null handles) and counts of 0.
struct GpuMesh {
  Buffer vertices;  // VERTEX_BUFFER usage (and storage, transfer)
  Buffer indices;   // INDEX_BUFFER usage, VK_INDEX_TYPE_UINT32
  uint32_t index_count = 0, vertex_count = 0;
};

// Binds the mesh's vertex and index buffers and draws it once; a mesh without triangles draws
// nothing (its buffers are null).
void draw_mesh(VkCommandBuffer cmd, const GpuMesh& mesh);

class GpuScene {
 public:
  // Uploads through a submitter of its own: it outlives the executors that draw with it.
  explicit GpuScene(Context& context);

  // Uploads the meshes and textures when `scene.version` differs from the last upload (the
  // first call always uploads). Throws std::invalid_argument naming a malformed mesh or
  // texture (attribute counts that differ, indices out of range, pixels of the wrong size, null).
  void update(const SceneView& scene);

  int mesh_count() const { return static_cast<int>(meshes_.size()); }
  const GpuMesh& mesh(int index) const { return meshes_.at(index); }
  // Per mesh, the box around its positions in its own space (what visible_draws() takes).
  std::span<const Bounds> mesh_bounds() const { return bounds_; }
  int texture_count() const { return static_cast<int>(textures_.size()); }
  // Texture `index` of SceneView::textures, or the white texture for -1.
  Image& texture(int index) { return index < 0 ? white_ : textures_.at(index); }
  Image& white_texture() { return white_; }
  // The sampler for `sampling`, made on first use and kept while the GpuScene lives.
  VkSampler sampler(const TextureSampling& sampling);

 private:
  GpuMesh upload(const MeshData& mesh);
  Image upload(const TextureData& texture);

  Context& context_;
  Submitter submitter_;
  std::optional<uint64_t> version_;
  std::vector<GpuMesh> meshes_;
  std::vector<Bounds> bounds_;
  std::vector<Image> textures_;
  Image white_;
  std::vector<std::pair<TextureSampling, std::unique_ptr<Sampler>>> samplers_;  // a handful: searched in turn
};

}  // namespace lg
