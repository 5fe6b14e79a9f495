// gi.planar_reflection's kernel. Its one pass, each frame:
//  1. chooses the reflector planes the camera is in front of, nearest first, up to max_planes;
//  2. draws each from the camera mirrored in it (mirror_camera.h) into a layer of a 2D array
//     image with the raster captures' code (raster_capture.h), what lies behind the plane clipped
//     and the distance from the mirrored camera in alpha;
//  3. builds the array's mip chain, each level a bilinear 2x2 average of the one above
//     (shaders/planar_downsample.comp);
//  4. looks the layers up per pixel (shaders/planar_lookup.comp).
#include "nodes/gi/planar_reflection/planar_reflection_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/gi/planar_reflection/mirror_camera.h"
#include "nodes/gi/reflection_capture/raster_capture.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

constexpr uint32_t kMaxPlanes = 8;  // shaders/planar_lookup.comp: LG_MAX_PLANES
constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

struct LookupPush {  // shaders/planar_lookup.comp
  uint32_t plane_count;
  uint32_t has_under;
  float texel_angle;
};

constexpr SyncScope kAttachmentWrite{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
constexpr SyncScope kComputeAccess{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};

// The planes with the camera in front, nearest first: no pixel sees the back of a mirror.
std::vector<glm::vec4> planes_to_draw(const SceneView& scene, uint32_t max_planes) {
  std::vector<glm::vec4> planes;
  for (const glm::vec4& p : scene.planar_reflectors)
    if (glm::dot(glm::vec3(p), scene.camera.position) + p.w > 0.0f) planes.push_back(p);
  const auto distance = [&](const glm::vec4& p) { return glm::dot(glm::vec3(p), scene.camera.position) + p.w; };
  std::sort(planes.begin(), planes.end(), [&](const glm::vec4& a, const glm::vec4& b) { return distance(a) < distance(b); });
  if (planes.size() > max_planes) planes.resize(max_planes);
  return planes;
}

class PlanarReflectionKernel final : public NodeKernel {
 public:
  explicit PlanarReflectionKernel(const PlanNode& node)
      : divisor_(resolution_divisor(node)),
        max_planes_(std::min(uint32_t(param_number(node, "max_planes")), kMaxPlanes)),
        mips_(uint32_t(param_number(node, "mips"))),
        intensity_(float(param_number(node, "intensity"))) {}

  void record(PassContext& ctx) override {
    if (ctx.pass().pass != "reflect")
      throw std::logic_error("gi.planar_reflection has no pass '" + ctx.pass().pass + "'");
    if (!capture_) {
      capture_.emplace(ctx.gpu(), ctx.node().id);
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      planes_buffer_.emplace(ctx.gpu(), ctx.node().id + " planes", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    }
    Image& depth = ctx.image("in.gbuffer", 0);
    const uint32_t width = std::max(1u, depth.desc().width / divisor_);
    const uint32_t height = std::max(1u, depth.desc().height / divisor_);
    const std::vector<glm::vec4> planes = planes_to_draw(ctx.scene(), max_planes_);
    prepare_views(ctx, width, height);
    draw_mirrored_views(ctx, planes, width, height);
    build_chain(ctx, uint32_t(planes.size()));
    lookup(ctx, planes, height);
  }

 private:
  void prepare_views(PassContext& ctx, uint32_t width, uint32_t height) {
    if (views_ && views_->desc().width == width && views_->desc().height == height) return;
    const uint32_t mips = std::min(mips_, uint32_t(std::bit_width(std::max(width, height))));
    views_.emplace(Image::dedicated(ctx.gpu(), {.name = ctx.node().id + " mirrored views",
                                                .format = kFormat,
                                                .width = width,
                                                .height = height,
                                                .mips = mips,
                                                .layers = max_planes_}));
  }

  void draw_mirrored_views(PassContext& ctx, const std::vector<glm::vec4>& planes, uint32_t width, uint32_t height) {
    // The old contents are not kept: every layer drawn is covered whole.
    image_barrier(ctx.cmd(), *views_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                  {kComputeAccess.stages, VK_ACCESS_2_NONE}, kAttachmentWrite);
    ForwardSettings settings{};
    const CaptureResources resources = inputs_.bind(ctx, intensity_, settings);
    settings.flags |= 4u;  // the distance to the mirrored camera in alpha
    std::vector<CaptureView> views;
    for (uint32_t i = 0; i < planes.size(); ++i)
      views.push_back({.camera = mirrored_camera(ctx.scene().camera, planes[i], width, height),
                       .target = views_->view(
                           {.type = VK_IMAGE_VIEW_TYPE_2D, .mip_count = 1, .base_layer = i, .layer_count = 1}),
                       .width = width,
                       .height = height,
                       .clip_plane = planes[i]});
    capture_->record_views(ctx, views, kFormat, resources, settings, false);
    image_barrier(ctx.cmd(), *views_, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, kAttachmentWrite,
                  kComputeAccess);
  }

  void build_chain(PassContext& ctx, uint32_t layers) {
    for (uint32_t level = 1; level < views_->desc().mips; ++level) {
      const uint32_t w = std::max(1u, views_->desc().width >> level), h = std::max(1u, views_->desc().height >> level);
      for (uint32_t layer = 0; layer < layers; ++layer) {
        const DescriptorWrite writes[] = {
            sampled_image(0, views_->view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = level - 1, .mip_count = 1}),
                          ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
            storage_image(1, views_->view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = level, .mip_count = 1}))};
        dispatch_compute(ctx, "nodes/gi/planar_reflection/shaders/planar_downsample.comp", writes, w, h,
                         std::as_bytes(std::span(&layer, 1)));
      }
      compute_to_compute_barrier(ctx.cmd());
    }
  }

  void lookup(PassContext& ctx, const std::vector<glm::vec4>& planes, uint32_t view_height) {
    Image& depth = ctx.image("in.gbuffer", 0);
    Image& out = ctx.image("out.reflections");
    const SceneView& scene = ctx.scene();
    camera_->write_value(camera_constants(scene.camera, depth.desc().width, depth.desc().height));
    std::array<glm::vec4, kMaxPlanes> packed{};
    std::copy(planes.begin(), planes.end(), packed.begin());
    planes_buffer_->write_value(packed);
    const bool under = ctx.has("in.reflections");
    // The angle one texel of a mirrored view spans at the centre: 2 tan(fov / 2) / height.
    const float texel_angle = 2.0f * std::tan(0.5f * scene.camera.vertical_fov) / float(view_height);
    const LookupPush push{uint32_t(planes.size()), under ? 1u : 0u, texel_angle};
    const DescriptorWrite writes[] = {
        uniform_buffer(0, camera_->handle()),
        sampled_image(1, depth.view(), ctx.nearest_sampler()),
        sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        uniform_buffer(4, planes_buffer_->handle()),
        sampled_image(5, views_->view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY}), ctx.linear_sampler(),
                      VK_IMAGE_LAYOUT_GENERAL),
        sampled_image(6, under ? ctx.image("in.reflections").view() : depth.view(), ctx.nearest_sampler()),
        storage_image(7, out.view())};
    dispatch_compute(ctx, "nodes/gi/planar_reflection/shaders/planar_lookup.comp", writes, out.desc().width,
                     out.desc().height, std::as_bytes(std::span(&push, 1)));
  }

  const uint32_t divisor_, max_planes_, mips_;
  const float intensity_;
  std::optional<RasterCapture> capture_;
  CaptureInputs inputs_;
  std::optional<HostBuffer> camera_, planes_buffer_;
  std::optional<Image> views_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_planar_reflection_kernel(const PlanNode& node) {
  return std::make_unique<PlanarReflectionKernel>(node);
}

}  // namespace lg
