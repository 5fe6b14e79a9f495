// occlusion.baked's kernel. Once per asset version (SceneView::version) the meshes' bakes go to
// the device: vertex bakes as one buffer of (bent normal, k_A) per vertex, lightmaps as one buffer
// of texels, and for each texel-baked mesh its own vertex buffer with three vertices a triangle
// whose uv is the corner's lightmap UV. Every frame the "raster" pass draws every mesh that the
// camera's frustum touches with its own depth test, as the G-buffer pass does, so the nearest
// surface wins in both; "resolve" turns that into ao and bent normals (shaders/baked_resolve.comp).
#include "nodes/occlusion/baked/baked_kernel.h"

#include <glm/mat3x3.hpp>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

enum BakeKind : uint32_t { no_bake = 0, vertex_bake = 1, texel_bake = 2 };  // shaders/baked_draw.glsl

struct BakedDraw {  // shaders/baked_draw.glsl
  uint32_t kind = no_bake, vertex_base = 0, lightmap_base = 0, lightmap_size = 0;
  glm::mat4 lightmap_to_world{1.0f};
};

// A mesh's bake on the device: where its data starts, and for texel bakes the vertex buffer
// of its triangle corners.
struct MeshBake {
  BakedDraw draw;
  std::optional<HostBuffer> corners;
  uint32_t corner_count = 0;
};

class BakedKernel final : public NodeKernel {
 public:
  explicit BakedKernel(const PlanNode& node) : cull_backfaces_(param_bool(node, "cull_backfaces")) {}

  void record(PassContext& ctx) override {
    if (ctx.pass().pass == "raster") return raster(ctx);
    if (ctx.pass().pass == "resolve") return resolve(ctx);
    throw std::logic_error("occlusion.baked has no pass '" + ctx.pass().pass + "'");
  }

 private:
  void upload(PassContext& ctx, const SceneView& scene) {
    if (uploaded_version_ == scene.version) return;
    if (!vertex_occlusion_) {
      vertex_occlusion_.emplace(ctx.gpu(), ctx.node().id + " vertex bakes", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      lightmaps_.emplace(ctx.gpu(), ctx.node().id + " lightmaps", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    std::vector<glm::vec4> vertices, texels;
    std::map<const OcclusionLightmap*, uint32_t> lightmap_base;  // meshes of one bake share its lightmap
    meshes_.clear();
    meshes_.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      if (!scene.meshes[m] || !scene.meshes[m]->occlusion) continue;
      const MeshData& mesh = *scene.meshes[m];
      const MeshOcclusion& bake = *mesh.occlusion;
      MeshBake& out = meshes_[m];
      if (bake.kind == MeshOcclusion::Kind::vertex) {
        if (bake.vertices.size() != mesh.positions.size())
          throw std::invalid_argument("mesh '" + mesh.name + "': its vertex bake '" + bake.source + "' holds " +
                                      std::to_string(bake.vertices.size()) + " vertices, the mesh " +
                                      std::to_string(mesh.positions.size()));
        out.draw = {vertex_bake, uint32_t(vertices.size()), 0, 0};
        vertices.insert(vertices.end(), bake.vertices.begin(), bake.vertices.end());
        continue;
      }
      if (!bake.lightmap || bake.lightmap_uvs.size() != mesh.indices.size())
        throw std::invalid_argument("mesh '" + mesh.name + "': its texel bake '" + bake.source + "' holds " +
                                    std::to_string(bake.lightmap_uvs.size()) + " triangle corners, the mesh " +
                                    std::to_string(mesh.indices.size()));
      auto [base, added] = lightmap_base.emplace(bake.lightmap.get(), uint32_t(texels.size()));
      if (added) texels.insert(texels.end(), bake.lightmap->texels.begin(), bake.lightmap->texels.end());
      out.draw = {texel_bake, 0, base->second, bake.lightmap->size};
      std::vector<GpuVertex> corners(mesh.indices.size());
      for (size_t c = 0; c < corners.size(); ++c) {
        const uint32_t v = mesh.indices[c];
        corners[c] = {{mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z},
                      {mesh.normals[v].x, mesh.normals[v].y, mesh.normals[v].z},
                      {bake.lightmap_uvs[c].x, bake.lightmap_uvs[c].y}};
      }
      out.corners.emplace(ctx.gpu(), ctx.node().id + " corners of '" + mesh.name + "'",
                          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
      out.corners->write(corners);
      out.corner_count = uint32_t(corners.size());
    }
    const uint64_t limit = ctx.gpu().properties().limits.maxStorageBufferRange;
    for (const auto& [what, bytes] : {std::pair{"vertex bakes", vertices.size() * sizeof(glm::vec4)},
                                      std::pair{"lightmaps", texels.size() * sizeof(glm::vec4)}})
      if (bytes > limit)
        throw std::invalid_argument("the scene's " + std::string(what) + " take " + std::to_string(bytes >> 20) +
                                    " MiB, more than the device's storage buffers hold (" +
                                    std::to_string(limit >> 20) + " MiB): bake smaller lightmaps");
    vertex_occlusion_->write(vertices);
    lightmaps_->write(texels);
    uploaded_version_ = scene.version;
  }

  void raster(PassContext& ctx) {
    const SceneView& scene = ctx.scene();
    upload(ctx, scene);
    Image& baked = ctx.image("tmp.baked");
    Image& depth = ctx.image("tmp.depth");
    const uint32_t w = baked.desc().width, h = baked.desc().height;
    if (!camera_) {
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      baked_draws_.emplace(ctx.gpu(), ctx.node().id + " baked draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    camera_->write_value(camera_constants(scene.camera, w, h));
    const std::vector<DrawConstants> draws = draw_constants(scene);
    draws_->write(draws);
    std::vector<BakedDraw> baked_draws;
    for (size_t i = 0; i < scene.draws.size(); ++i) {
      const int mesh = scene.draws[i].mesh;
      BakedDraw& b = baked_draws.emplace_back();
      if (mesh < 0 || size_t(mesh) >= meshes_.size()) continue;
      b = meshes_[size_t(mesh)].draw;
      if (b.kind == texel_bake)
        b.lightmap_to_world =
            glm::mat4(glm::mat3(draws[i].normal_matrix) * scene.meshes[size_t(mesh)]->occlusion->lightmap_to_mesh);
    }
    baked_draws_->write(baked_draws);

    VkRenderingAttachmentInfo color = cleared_attachment(baked.view(), {.color = {{0.0f, 0.0f, 0.0f, -1.0f}}});
    VkRenderingAttachmentInfo depth_attachment =
        cleared_attachment(depth.view(), {.depthStencil = {0.0f, 0}});  // reversed Z: 0 is infinity
    const VkRenderingInfo rendering = rendering_info(w, h, {&color, 1}, &depth_attachment);

    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    const Pipeline& pipeline = this->pipeline(ctx, baked, depth);
    set_viewport(cmd, w, h);
    const DescriptorWrite writes[] = {uniform_buffer(0, camera_->handle()), storage_buffer(1, draws_->handle()),
                                      storage_buffer(2, baked_draws_->handle()),
                                      storage_buffer(3, vertex_occlusion_->handle()),
                                      storage_buffer(4, lightmaps_->handle())};
    bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
    // As the G-buffer pass: only the draws the camera's frustum touches.
    for (uint32_t i : visible_draws(scene, ctx.gpu_scene().mesh_bounds(), view_frustum(scene.camera))) {
      const DrawItem& d = scene.draws[i];
      push_constants(cmd, pipeline, i);
      const MeshBake* bake = baked_draws[i].kind == texel_bake ? &meshes_[size_t(d.mesh)] : nullptr;
      if (!bake) {
        draw_mesh(cmd, ctx.gpu_scene().mesh(d.mesh));
        continue;
      }
      const VkBuffer corners = bake->corners->handle();
      const VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(cmd, 0, 1, &corners, &offset);
      vkCmdDraw(cmd, bake->corner_count, 1, 0, 0);
    }
    vkCmdEndRendering(cmd);
  }

  void resolve(PassContext& ctx) {
    Image& ao = ctx.image("out.ao");
    // Without the drawing pass (no baked mesh: the plan dropped it and tmp.baked with it) the
    // shader reads nothing at binding 2; the G-buffer normal stands in so that it binds.
    const uint32_t drawn = ctx.has("tmp.baked") ? 1u : 0u;
    Image& baked = drawn ? ctx.image("tmp.baked") : ctx.image("in.gbuffer", 1);
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      sampled_image(2, baked.view(), ctx.nearest_sampler()),
                                      storage_image(3, ao.view()),
                                      storage_image(4, ctx.image("out.bent_normals").view())};
    dispatch_compute(ctx, "nodes/occlusion/baked/shaders/baked_resolve.comp", writes, ao.desc().width, ao.desc().height,
                     std::as_bytes(std::span(&drawn, 1)));
  }

  const Pipeline& pipeline(PassContext& ctx, const Image& baked, const Image& depth) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader("nodes/occlusion/baked/shaders/baked_raster.vert");
    desc.fragment_shader = node_shader("nodes/occlusion/baked/shaders/baked_raster.frag");
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                     {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    desc.push_constant_bytes = sizeof(uint32_t);
    use_gpu_vertices(desc);
    desc.cull = cull_backfaces_ ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;  // winding as the G-buffer pass's
    desc.color_formats.push_back(baked.desc().format);
    desc.depth_format = depth.desc().format;
    desc.depth_test = desc.depth_write = true;
    return ctx.pipelines().graphics(desc);
  }

  bool cull_backfaces_;
  std::optional<uint64_t> uploaded_version_;
  std::vector<MeshBake> meshes_;  // per SceneView::meshes entry
  std::optional<HostBuffer> camera_, draws_, baked_draws_, vertex_occlusion_, lightmaps_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_baked_kernel(const PlanNode& node) {
  return std::make_unique<BakedKernel>(node);
}

}  // namespace lg
