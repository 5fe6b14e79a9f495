// gi.prt's kernel (prt_kernel.h): one graphics pass that first dispatches the per-vertex
// dot products, then draws. The bake is read when the plan is made, so a missing or bad
// file fails before any frame; it is checked against the scene's geometry (the world mesh's hash
// and draw count) and sent to the device again only when the assets change or a draw moves.
#include "nodes/gi/prt/prt_kernel.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/env/common/sh_basis.h"
#include "nodes/env/common/sh_rotation.h"
#include "nodes/gi/prt/prt_file.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

constexpr uint32_t kRowWidth = 256;  // shaders/prt_vertices.comp

struct VerticesPush {  // shaders/prt_vertices.comp
  uint32_t vertices, stride, order, clamp_negative;
};

// The environment's rotation this frame: yaw about +Y (growing by `spin` a frame), then pitch
// about +X.
glm::dmat3 environment_rotation(double yaw, double pitch, double spin, uint64_t frame) {
  const double turn = glm::radians(yaw + spin * double(frame));
  const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), turn, glm::dvec3(0, 1, 0)) *
                       glm::rotate(glm::dmat4(1.0), glm::radians(pitch), glm::dvec3(1, 0, 0));
  return glm::dmat3(r);
}

class PrtKernel final : public NodeKernel {
 public:
  explicit PrtKernel(const PlanNode& node)
      : bake_path_(param_string(node, "bake")),
        file_(read_prt_file(bake_path_)),
        order_(std::min(int(param_number(node, "order")), file_.header.settings.order)),
        yaw_(param_number(node, "yaw")),
        pitch_(param_number(node, "pitch")),
        spin_(param_number(node, "spin")),
        clamp_negative_(param_bool(node, "clamp_negative")),
        cull_backfaces_(param_bool(node, "cull_backfaces")) {
    if (file_.header.chunk_count != 1)
      throw std::invalid_argument(bake_path_ + ": is chunk " + std::to_string(file_.header.chunk_index) + " of " +
                                  std::to_string(file_.header.chunk_count) +
                                  "; merge the parts first (lumagraph bake merge)");
  }

  void record(PassContext& ctx) override {
    if (ctx.pass().pass != "shade") throw std::logic_error("gi.prt has no pass '" + ctx.pass().pass + "'");
    upload(ctx, ctx.scene());
    vertices(ctx);
    raster(ctx);
  }

 private:
  // The bake on the device, once it is known to belong to the scene's geometry: checked again
  // when the assets change or a draw moves (the transfer belongs to where each mesh stood).
  void upload(PassContext& ctx, const SceneView& scene) {
    std::vector<glm::mat4> placement;
    for (const DrawItem& d : scene.draws) placement.push_back(d.world);
    if (uploaded_version_ == scene.version && placement == uploaded_placement_) return;
    const WorldMesh mesh = make_world_mesh(scene);
    const PrtFileHeader& h = file_.header;
    if (world_mesh_hash(mesh) != h.input_hash || mesh.parts.size() != h.parts.size())
      throw std::invalid_argument(bake_path_ + ": was baked from other geometry (" + std::to_string(h.parts.size()) +
                                  " draws, " + std::to_string(h.vertices) + " vertices, hash " + hex64(h.input_hash) +
                                  ") than the scene's (" + std::to_string(mesh.parts.size()) + " draws, " +
                                  std::to_string(mesh.positions.size()) + " vertices, hash " +
                                  hex64(world_mesh_hash(mesh)) + "); bake it again (lumagraph bake --mode prt)");
    const size_t floats = size_t(prt_vertex_floats(h.settings.order)), stride = floats + 1;
    std::vector<float> packed(h.vertices * stride);
    for (size_t v = 0; v < h.vertices; ++v) {
      std::copy_n(file_.data.transfer.begin() + v * floats, floats, packed.begin() + v * stride);
      packed[v * stride + floats] = file_.data.valid[v];
    }
    const uint64_t bytes = packed.size() * sizeof(float), limit = ctx.gpu().properties().limits.maxStorageBufferRange;
    if (bytes > limit)
      throw std::invalid_argument(bake_path_ + ": its transfer takes " + std::to_string(bytes >> 20) +
                                  " MiB, more than the device's storage buffers hold (" + std::to_string(limit >> 20) +
                                  " MiB): bake a lower order or fewer vertices");
    transfer_.emplace(ctx.gpu(), ctx.node().id + " transfer", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    transfer_->write(packed);
    vertex_irradiance_ = Buffer::dedicated(ctx.gpu(), {.name = ctx.node().id + " vertex irradiance",
                                                       .size = std::max<uint64_t>(h.vertices, 1) * 16,
                                                       .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT});
    std::vector<uint32_t> bases;
    for (const WorldMesh::Part& p : mesh.parts) bases.push_back(p.first_vertex);
    if (!draw_bases_) draw_bases_.emplace(ctx.gpu(), ctx.node().id + " draw bases", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    draw_bases_->write(bases);
    uploaded_version_ = scene.version;
    uploaded_placement_ = std::move(placement);
  }

  // The vertices' irradiance into the kernel's own buffer, read by raster()'s vertex stage.
  void vertices(PassContext& ctx) {
    // The plan makes the SH visible to the pass's fragment stage (a graphics pass); this
    // dispatch reads it earlier, in the compute stage, where env.sh_project wrote it. The same
    // barrier orders this write of the vertices' buffer after any earlier drawing's reads.
    memory_barrier(ctx.cmd(),
                   {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                   {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const Buffer& sh = ctx.buffer("in.sh");
    // The SH input's order from its size: the lowest of it, the node's and the bake's is used.
    int sh_order = 0;
    while (sh_order < kMaxShOrder && uint64_t(sh_count(sh_order + 1)) * 16 <= sh.size()) ++sh_order;
    const int order = std::min(order_, sh_order);
    const ShRotation turn = sh_rotation(order, environment_rotation(yaw_, pitch_, spin_, ctx.frame_index()));
    if (!rotation_) rotation_.emplace(ctx.gpu(), ctx.node().id + " rotation", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    rotation_->write(std::vector<float>(turn.blocks.begin(), turn.blocks.end()));
    const uint32_t count = uint32_t(file_.header.vertices);
    const VerticesPush push{count, uint32_t(prt_vertex_floats(file_.header.settings.order) + 1), uint32_t(order),
                            clamp_negative_ ? 1u : 0u};
    const DescriptorWrite writes[] = {storage_buffer(0, sh.handle()), storage_buffer(1, rotation_->handle()),
                                      storage_buffer(2, transfer_->handle()),
                                      storage_buffer(3, vertex_irradiance_.handle())};
    dispatch_compute(ctx, "nodes/gi/prt/shaders/prt_vertices.comp", writes, kRowWidth,
                     std::max(1u, (count + kRowWidth - 1) / kRowWidth), std::as_bytes(std::span(&push, 1)));
    // The vertex stage reads what this wrote (and the next frame's dispatch must not overwrite
    // it before: frames are serial, the executor waits for each).
    memory_barrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                   {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
  }

  void raster(PassContext& ctx) {
    const SceneView& scene = ctx.scene();
    Image& out = ctx.image("out.irradiance");
    Image& depth = ctx.image("tmp.depth");
    const uint32_t w = out.desc().width, h = out.desc().height;
    if (!camera_) {
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    camera_->write_value(camera_constants(scene.camera, w, h));
    draws_->write(draw_constants(scene));

    VkRenderingAttachmentInfo color = cleared_attachment(out.view());  // sky: 0, coverage 0
    VkRenderingAttachmentInfo depth_attachment =
        cleared_attachment(depth.view(), {.depthStencil = {0.0f, 0}});  // reversed Z: 0 is infinity
    const VkRenderingInfo rendering = rendering_info(w, h, {&color, 1}, &depth_attachment);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    const Pipeline& pipeline = this->pipeline(ctx, out, depth);
    set_viewport(cmd, w, h);
    const DescriptorWrite writes[] = {uniform_buffer(0, camera_->handle()), storage_buffer(1, draws_->handle()),
                                      storage_buffer(2, draw_bases_->handle()),
                                      storage_buffer(3, vertex_irradiance_.handle())};
    bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
    // As the G-buffer pass: only the draws the camera's frustum touches, nearest surface wins.
    for (uint32_t i : visible_draws(scene, ctx.gpu_scene().mesh_bounds(), view_frustum(scene.camera))) {
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, ctx.gpu_scene().mesh(scene.draws[i].mesh));
    }
    vkCmdEndRendering(cmd);
  }

  const Pipeline& pipeline(PassContext& ctx, const Image& out, const Image& depth) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader("nodes/gi/prt/shaders/prt_raster.vert");
    desc.fragment_shader = node_shader("nodes/gi/prt/shaders/prt_raster.frag");
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                     {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    desc.push_constant_bytes = sizeof(uint32_t);
    use_gpu_vertices(desc);
    desc.vertex_attributes.resize(1);                                         // the position alone
    desc.cull = cull_backfaces_ ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;  // winding as the G-buffer pass's
    desc.color_formats.push_back(out.desc().format);
    desc.depth_format = depth.desc().format;
    desc.depth_test = desc.depth_write = true;
    return ctx.pipelines().graphics(desc);
  }

  std::string bake_path_;
  PrtFile file_;
  int order_;
  double yaw_, pitch_, spin_;
  bool clamp_negative_, cull_backfaces_;
  std::optional<uint64_t> uploaded_version_;
  std::vector<glm::mat4> uploaded_placement_;
  std::optional<HostBuffer> transfer_, draw_bases_, rotation_, camera_, draws_;
  Buffer vertex_irradiance_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_prt_kernel(const PlanNode& node) {
  return std::make_unique<PrtKernel>(node);
}

}  // namespace lg
