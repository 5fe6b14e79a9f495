// gi.reflection_capture's kernel. The "lookup" pass first makes sure the cubes are current, then
// one dispatch looks them up per pixel (shaders/reflection_lookup.comp).
//
// capture "raster" (raster_capture.h): with faces_per_frame 0, when
// reflection_capture_key() of the frame's scene or the linked irradiance volume's probes
// (probe_volume: their upload version) differ from the last capture's, every face of
// every probe is drawn on the GPU and every probe prefiltered; with faces_per_frame N, the whole
// capture is drawn on the first frame (and when the number of probes changes), then N faces a
// frame, round robin over the probes and their faces, whatever changed, and a probe is
// prefiltered again when its sixth face is drawn. second_bounce draws the capture again with each
// probe's first capture as the specular map of the surfaces it sees.
//
// capture "path_traced": every probe's cube is traced on the CPU (reflection_cube_capture.h,
// under the plan's own environment, plan_environment()) when the key changes, then uploaded.
//
// Prefiltering is env.specular_prefilter's record_specular_prefilter() (probe_cubes.h).
#include "nodes/gi/reflection_capture/reflection_capture_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/gi/irradiance_volume/probe_bake_key.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "nodes/gi/reflection_capture/captured_cube_source.h"
#include "nodes/gi/reflection_capture/probe_cubes.h"
#include "nodes/gi/reflection_capture/raster_capture.h"
#include "nodes/gi/reflection_capture/reflection_cube_capture.h"
#include "nodes/gi/reflection_capture/reflection_probe_buffer.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/texel_codec.h"
#include "runtime/gpu/transfer.h"

namespace lg {
namespace {

struct Push {  // shaders/reflection_lookup.comp
  uint32_t probe_count;
};

constexpr SyncScope kTransferWrite{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
constexpr SyncScope kComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};

class ReflectionCaptureKernel final : public NodeKernel, public CapturedCubeSource {
 public:
  explicit ReflectionCaptureKernel(const PlanNode& node)
      : raster_(param_string(node, "capture") == "raster"),
        second_bounce_(param_bool(node, "second_bounce")),
        faces_per_frame_(uint32_t(param_number(node, "faces_per_frame"))),
        prefilter_samples_(uint32_t(param_number(node, "prefilter_samples"))),
        intensity_(float(param_number(node, "intensity"))) {
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
    }
    const SceneView& scene = ctx.scene();
    const uint64_t key = reflection_capture_key(scene);
    // The raster capture reads the linked volume's probes: new probes (a bake, a dynamic update
    // landing) make the cubes stale too.
    const uint64_t volume = raster_ ? CaptureInputs::volume_version(ctx) : 0;
    const bool fresh = cubes_.prepare(ctx, scene.reflection_probes.size(), settings_.face_size, mips_);
    const bool changed = fresh || key != captured_key_ || volume != captured_volume_;
    if (changed) {
      probe_buffer_->write(pack_reflection_probes(scene, "gi.reflection_capture '" + ctx.node().id + "'"));
      push_.probe_count = uint32_t(scene.reflection_probes.size());
    }
    if (!raster_) {
      if (changed) capture_traced(ctx);
    } else if (faces_per_frame_ == 0 || fresh) {
      if (changed) capture_raster_all(ctx);
    } else {
      capture_raster_slice(ctx);
    }
    captured_key_ = key;
    captured_volume_ = volume;
    lookup(ctx);
  }

  std::vector<float> read_captured_face(Submitter& submitter, uint32_t probe, int face) override {
    if (probe >= cubes_.captured().size() || face < 0 || face > 5)
      throw std::out_of_range("gi.reflection_capture: no captured face " + std::to_string(face) + " of probe " +
                              std::to_string(probe));
    return read_image(submitter, cubes_.captured()[probe], VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, {0, uint32_t(face)});
  }

 private:
  void lookup(PassContext& ctx) {
    const Image& depth = ctx.image("in.gbuffer", 0);
    Image& out = ctx.image("out.reflections");
    camera_->write_value(camera_constants(ctx.scene().camera, depth.desc().width, depth.desc().height));
    const DescriptorWrite writes[] = {
        uniform_buffer(0, camera_->handle()),
        sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
        sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        uniform_buffer(4, probe_buffer_->handle()),
        sampled_image(5, cubes_.array().view({.type = VK_IMAGE_VIEW_TYPE_CUBE_ARRAY}), ctx.linear_sampler()),
        storage_image(6, out.view())};
    dispatch_compute(ctx, "nodes/gi/reflection_capture/shaders/reflection_lookup.comp", writes, out.desc().width,
                     out.desc().height, std::as_bytes(std::span(&push_, 1)), kTileSize, constants_);
  }

  // Draws `faces`, reading the probes' own cubes as specular map when `probe_specular`.
  void draw_faces(PassContext& ctx, std::span<const CubeFace> faces, bool probe_specular) {
    if (!raster_capture_) raster_capture_.emplace(ctx.gpu(), ctx.node().id);
    ForwardSettings settings{};
    const CaptureResources resources = inputs_.bind(ctx, intensity_, settings);
    std::vector<VkImageView> specular;
    if (probe_specular)
      for (uint32_t p = 0; p < cubes_.captured().size(); ++p) specular.push_back(cubes_.cube_view(p));
    raster_capture_->record(ctx, faces, cubes_.captured(), resources, settings, specular);
  }

  void capture_raster_all(PassContext& ctx) {
    const auto start = std::chrono::steady_clock::now();
    const uint32_t count = uint32_t(cubes_.captured().size());
    std::vector<CubeFace> faces;
    for (uint32_t p = 0; p < count; ++p)
      for (int f = 0; f < 6; ++f) faces.push_back({p, f});
    std::vector<uint32_t> probes(count);
    std::iota(probes.begin(), probes.end(), 0u);
    for (int bounce = 0; bounce < (second_bounce_ ? 2 : 1); ++bounce) {
      draw_faces(ctx, faces, bounce > 0);
      cubes_.prefilter(ctx, probes, prefilter_samples_);
    }
    next_face_ = 0;
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr,
                 "gi.reflection_capture '%s': captured %u probe(s), %ux%u faces, raster%s (recorded in %.1f ms)\n",
                 ctx.node().id.c_str(), count, settings_.face_size, settings_.face_size,
                 second_bounce_ ? ", two bounces" : "", ms);
  }

  // faces_per_frame faces from where the last frame stopped; each probe whose last face is among
  // them has six new faces and is prefiltered.
  void capture_raster_slice(PassContext& ctx) {
    const uint32_t slots = uint32_t(6 * cubes_.captured().size());
    if (slots == 0) return;
    std::vector<CubeFace> faces;
    std::vector<uint32_t> complete;
    for (uint32_t k = 0; k < std::min(faces_per_frame_, slots); ++k) {
      const uint32_t slot = (next_face_ + k) % slots;
      faces.push_back({slot / 6, int(slot % 6)});
      if (slot % 6 == 5) complete.push_back(slot / 6);
    }
    next_face_ = (next_face_ + uint32_t(faces.size())) % slots;
    draw_faces(ctx, faces, second_bounce_);
    cubes_.prefilter(ctx, complete, prefilter_samples_);
  }

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

  void capture_traced(PassContext& ctx) {
    const SceneView& scene = ctx.scene();
    const auto start = std::chrono::steady_clock::now();
    SceneView seen = scene;  // what the probes see: every bounce of their paths misses the rest
    std::erase_if(seen.draws, [](const DrawItem& d) { return !d.captured_by_probes; });
    const PathScene traced(seen, environment(ctx));
    const size_t count = scene.reflection_probes.size();
    const uint32_t size = settings_.face_size;
    const FormatInfo& format = format_info(ProbeCubes::kFormat);
    const size_t cube_bytes = 6 * size_t(size) * size * format.bytes_per_texel;
    // Every probe's six faces as rgba16f, one after the other.
    std::vector<std::byte> bytes(count * cube_bytes);
    std::vector<float> rgba(6 * size_t(size) * size * 4);
    for (size_t i = 0; i < count; ++i) {
      const CubeImage cube =
          capture_reflection_cube(traced, glm::dvec3(scene.reflection_probes[i].world[3]), uint32_t(i), settings_);
      for (size_t t = 0; t < cube.texels.size(); ++t)
        for (int c = 0; c < 4; ++c) rgba[t * 4 + c] = float(cube.texels[t][c]);
      encode_texels(format, rgba, std::span(bytes).subspan(i * cube_bytes, cube_bytes));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!staging_) staging_.emplace(ctx.gpu(), ctx.node().id + " capture staging", VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    staging_->write(std::span<const std::byte>(bytes));
    VkCommandBuffer cmd = ctx.cmd();
    std::vector<uint32_t> probes;
    for (uint32_t i = 0; i < count; ++i) {
      Image& cube = cubes_.captured()[i];
      image_barrier(cmd, cube, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    {kComputeRead.stages, VK_ACCESS_2_NONE}, kTransferWrite);
      VkBufferImageCopy region{};
      region.bufferOffset = i * cube_bytes;
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
      region.imageExtent = {size, size, 1};
      vkCmdCopyBufferToImage(cmd, staging_->handle(), cube.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      image_barrier(cmd, cube, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, kTransferWrite,
                    kComputeRead);
      probes.push_back(i);
    }
    cubes_.prefilter(ctx, probes, prefilter_samples_);
    std::fprintf(
        stderr,
        "gi.reflection_capture '%s': captured %zu probe(s), %ux%u faces, %u paths a texel, %u bounces, in %.2f s\n",
        ctx.node().id.c_str(), count, size, size, settings_.samples, settings_.bounces, seconds);
  }

  const bool raster_, second_bounce_;
  const uint32_t faces_per_frame_, prefilter_samples_;
  const float intensity_;
  ReflectionCaptureSettings settings_;
  uint32_t mips_ = 1;
  std::array<uint32_t, 1> constants_{};  // shaders/reflection_lookup.comp: parallax
  Push push_{};
  uint64_t captured_key_ = 0, captured_volume_ = 0;  // the volume's upload version (CaptureInputs)
  uint32_t next_face_ = 0;                           // the time-sliced capture's next slot (6 probe + face)
  std::optional<HostBuffer> camera_, probe_buffer_, staging_;
  CaptureInputs inputs_;
  std::optional<PathEnvironment> environment_;
  bool environment_has_ = false;
  ProbeCubes cubes_;
  std::optional<RasterCapture> raster_capture_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_reflection_capture_kernel(const PlanNode& node) {
  return std::make_unique<ReflectionCaptureKernel>(node);
}

}  // namespace lg
