// gi.reflection_capture's kernel. The "lookup" pass first makes sure the cubes are current: when
// reflection_capture_key() of the frame's scene differs from the last capture's, every probe's
// cube is captured again on the CPU (reflection_cube_capture.h, under the plan's own environment,
// plan_environment()), uploaded, prefiltered on the GPU into a GGX mip chain by
// env.specular_prefilter's record_specular_prefilter() and copied into one cube array, cube i
// for probe i; otherwise the cubes on the device stay as they are. Then one dispatch looks them
// up per pixel (shaders/reflection_lookup.comp).
#include "nodes/gi/reflection_capture/reflection_capture_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdio>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "nodes/gi/irradiance_volume/probe_bake_key.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "nodes/gi/reflection_capture/reflection_cube_capture.h"
#include "nodes/gi/reflection_capture/reflection_probe_buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/texel_codec.h"

namespace lg {
namespace {

constexpr VkFormat kCubeFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

struct Push {  // shaders/reflection_lookup.comp
  uint32_t probe_count;
};

constexpr SyncScope kTransferWrite{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
constexpr SyncScope kTransferRead{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
constexpr SyncScope kComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
constexpr SyncScope kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr SyncScope kNothing{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};

Image cube_image(Context& gpu, const std::string& name, uint32_t size, uint32_t mips, uint32_t cubes = 1) {
  return Image::dedicated(gpu, {.name = name,
                                .kind = ImageKind::cube,
                                .format = kCubeFormat,
                                .width = size,
                                .height = size,
                                .mips = mips,
                                .layers = 6 * cubes});
}

// One probe's images while it is prefiltered: its captured radiance, the prefilter's chain and
// the prefiltered result, kept until the next capture (the frame that records them may still run).
struct ProbeImages {
  Image captured, chain, prefiltered;
};

class ReflectionCaptureKernel final : public NodeKernel {
 public:
  explicit ReflectionCaptureKernel(const PlanNode& node)
      : prefilter_samples_(uint32_t(param_number(node, "prefilter_samples"))) {
    settings_.face_size = uint32_t(param_number(node, "face_size"));
    settings_.samples = uint32_t(param_number(node, "samples"));
    settings_.bounces = uint32_t(param_number(node, "bounces"));
    settings_.seed = uint64_t(param_number(node, "seed"));
    // face_size is a power of two (the schema's values); no mip smaller than one texel.
    mips_ = std::min(uint32_t(param_number(node, "mips")), uint32_t(std::bit_width(settings_.face_size)));
    constants_ = {param_bool(node, "parallax") ? 1u : 0u};
  }

  void record(PassContext& ctx) override {
    if (ctx.pass().pass != "lookup")
      throw std::logic_error("gi.reflection_capture has no pass '" + ctx.pass().pass + "'");
    if (!camera_) {
      if (!ctx.gpu().image_cube_array())
        throw std::runtime_error("gi.reflection_capture '" + ctx.node().id +
                                 "': the device has no imageCubeArray feature enabled, which the probe lookup needs");
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      probe_buffer_.emplace(ctx.gpu(), ctx.node().id + " probes", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      staging_.emplace(ctx.gpu(), ctx.node().id + " capture staging", VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    }
    const uint64_t key = reflection_capture_key(ctx.scene());
    if (!cubes_ || key != captured_key_) capture(ctx, key);
    const Image& depth = ctx.image("in.gbuffer", 0);
    Image& out = ctx.image("out.reflections");
    camera_->write_value(camera_constants(ctx.scene().camera, depth.desc().width, depth.desc().height));
    const DescriptorWrite writes[] = {
        uniform_buffer(0, camera_->handle()),
        sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
        sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        uniform_buffer(4, probe_buffer_->handle()),
        sampled_image(5, cubes_->view({.type = VK_IMAGE_VIEW_TYPE_CUBE_ARRAY}), ctx.linear_sampler()),
        storage_image(6, out.view())};
    dispatch_compute(ctx, "nodes/gi/reflection_capture/shaders/reflection_lookup.comp", writes, out.desc().width,
                     out.desc().height, std::as_bytes(std::span(&push_, 1)), kTileSize, constants_);
  }

 private:
  // The plan's environment for the CPU tracer, loaded once (per environment presence).
  const PathEnvironment& environment(PassContext& ctx) {
    const bool has = ctx.scene().has_environment;
    if (!environment_ || environment_has_ != has) {
      const std::string who = "gi.reflection_capture '" + ctx.node().id + "'";
      environment_.emplace(plan_environment(ctx.plan(), has, who.c_str()));
      environment_has_ = has;
    }
    return *environment_;
  }

  void capture(PassContext& ctx, uint64_t key) {
    const SceneView& scene = ctx.scene();
    const std::string who = "gi.reflection_capture '" + ctx.node().id + "'";
    probe_buffer_->write(pack_reflection_probes(scene, who));
    const auto start = std::chrono::steady_clock::now();
    const PathScene traced(scene, environment(ctx));
    const size_t count = scene.reflection_probes.size();
    const uint32_t size = settings_.face_size;
    const size_t face_texels = size_t(size) * size;
    // Every probe's six faces as rgba16f, one after the other.
    const FormatInfo& format = format_info(kCubeFormat);
    std::vector<std::byte> bytes(count * 6 * face_texels * format.bytes_per_texel);
    std::vector<float> rgba(6 * face_texels * 4);
    for (size_t i = 0; i < count; ++i) {
      const CubeImage cube =
          capture_reflection_cube(traced, glm::dvec3(scene.reflection_probes[i].world[3]), uint32_t(i), settings_);
      for (size_t t = 0; t < cube.texels.size(); ++t)
        for (int c = 0; c < 4; ++c) rgba[t * 4 + c] = float(cube.texels[t][c]);
      const size_t cube_bytes = rgba.size() / 4 * format.bytes_per_texel;
      encode_texels(format, rgba, std::span(bytes).subspan(i * cube_bytes, cube_bytes));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    staging_->write(std::span<const std::byte>(bytes));
    record_cubes(ctx, count);
    captured_key_ = key;
    push_.probe_count = uint32_t(count);
    std::fprintf(stderr, "%s: captured %zu probe(s), %ux%u faces, %u paths a texel, %u bounces, in %.2f s\n",
                 who.c_str(), count, size, size, settings_.samples, settings_.bounces, seconds);
  }

  // Uploads the staged cubes, prefilters each and copies the results into the cube array.
  void record_cubes(PassContext& ctx, size_t count) {
    Context& gpu = ctx.gpu();
    VkCommandBuffer cmd = ctx.cmd();
    const uint32_t size = settings_.face_size;
    const std::string& name = ctx.node().id;
    probes_.clear();
    // An empty scene still binds a cube array (of one black cube).
    cubes_.emplace(cube_image(gpu, name + " prefiltered cubes", size, mips_, uint32_t(std::max<size_t>(count, 1))));
    image_barrier(cmd, *cubes_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kNothing,
                  kTransferWrite);
    if (count == 0) {
      const VkClearColorValue zero{};
      const VkImageSubresourceRange range = cubes_->whole_range();
      vkCmdClearColorImage(cmd, cubes_->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    }
    const uint64_t cube_bytes = uint64_t(6) * size * size * format_info(kCubeFormat).bytes_per_texel;
    for (size_t i = 0; i < count; ++i) {
      const std::string probe = name + " probe " + std::to_string(i);
      ProbeImages& p =
          probes_.emplace_back(ProbeImages{cube_image(gpu, probe + " captured", size, 1),
                                           cube_image(gpu, probe + " chain", size, uint32_t(std::bit_width(size))),
                                           cube_image(gpu, probe + " prefiltered", size, mips_)});
      image_barrier(cmd, p.captured, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kNothing,
                    kTransferWrite);
      VkBufferImageCopy region{};
      region.bufferOffset = i * cube_bytes;
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
      region.imageExtent = {size, size, 1};
      vkCmdCopyBufferToImage(cmd, staging_->handle(), p.captured.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                             &region);
      image_barrier(cmd, p.captured, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                    kTransferWrite, kComputeRead);
      for (Image* image : {&p.chain, &p.prefiltered})
        image_barrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kNothing, kComputeWrite);
      record_specular_prefilter(gpu, ctx.pipelines(), cmd, ctx.pass().name + " prefilter", prefilter_samples_,
                                p.captured, &p.chain, ctx.linear_sampler(), p.prefiltered, PrefilterSampling::filtered);
      image_barrier(cmd, p.prefiltered, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kComputeWrite,
                    kTransferRead);
      std::vector<VkImageCopy> copies;
      for (uint32_t mip = 0; mip < mips_; ++mip) {
        VkImageCopy copy{};
        copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, 6};
        copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, uint32_t(6 * i), 6};
        const uint32_t m = std::max(1u, size >> mip);
        copy.extent = {m, m, 1};
        copies.push_back(copy);
      }
      vkCmdCopyImage(cmd, p.prefiltered.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, cubes_->handle(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(copies.size()), copies.data());
    }
    image_barrier(cmd, *cubes_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, kTransferWrite,
                  kComputeRead);
  }

  ReflectionCaptureSettings settings_;
  uint32_t prefilter_samples_ = 0, mips_ = 1;
  std::array<uint32_t, 1> constants_{};  // shaders/reflection_lookup.comp: parallax
  Push push_{};
  uint64_t captured_key_ = 0;
  std::optional<HostBuffer> camera_, probe_buffer_, staging_;
  std::optional<PathEnvironment> environment_;
  bool environment_has_ = false;
  std::vector<ProbeImages> probes_;
  std::optional<Image> cubes_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_reflection_capture_kernel(const PlanNode& node) {
  return std::make_unique<ReflectionCaptureKernel>(node);
}

}  // namespace lg
