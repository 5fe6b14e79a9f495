// gi.irradiance_volume's kernel. The "lookup" pass first makes sure the probes are current. In
// the static mode, when probe_bake_key() of the frame's scene differs from the last bake's, every
// volume is baked again with bake_probes() (Embree on every core, the path tracer's transport
// under the plan's own environment, plan_environment()) and uploaded as an atlas
// (probe_atlas.h); otherwise the probes on the device stay as they are. In the dynamic mode the
// first frame (and one whose volumes changed) bakes so; later frames upload the probes of a batch
// of updates that has finished on the worker thread (probe_updater.h) and start the next one,
// never waiting for it. Then one dispatch looks them up per pixel, at full resolution into the
// output, or at resolution_scale into a smaller image that the "upsample" pass brings back to
// full resolution (nodes/common/shaders/joint_upsample.glsl); the lookup pass also copies the
// volumes' block into the `probes` output, and lends the atlas to the nodes reading it
// (probe_volume_source.h). Between frames it hands a copy of the probes it uploaded last to
// whoever asks (probe_snapshot.h).
#include "nodes/gi/irradiance_volume/irradiance_volume_kernel.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/gi/irradiance_volume/probe_atlas.h"
#include "nodes/gi/irradiance_volume/probe_atlas_images.h"
#include "nodes/gi/irradiance_volume/probe_bake_key.h"
#include "nodes/gi/irradiance_volume/probe_snapshot.h"
#include "nodes/gi/irradiance_volume/probe_updater.h"
#include "nodes/gi/irradiance_volume/probe_volume_source.h"
#include "nodes/gi/path_tracer/plan_environment.h"
#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_lookup.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

struct Push {  // shaders/irradiance_volume.comp
  uint32_t volume_count;
  float normal_bias;
  float view_bias;
  int32_t k;  // the G-buffer's resolution over the lookup target's: 1 / resolution_scale
};

// Counts uploads across every kernel, so a snapshot's version never repeats (probe_snapshot.h).
std::atomic<uint64_t> uploads{0};

class IrradianceVolumeKernel final : public NodeKernel, public ProbeSnapshotSource, public ProbeVolumeSource {
 public:
  explicit IrradianceVolumeKernel(const PlanNode& node) {
    settings_.rays = uint32_t(param_number(node, "rays"));
    settings_.bounces = uint32_t(param_number(node, "bounces"));
    settings_.seed = uint64_t(param_number(node, "seed"));
    const std::optional<ProbeRepresentation> r = parse_probe_representation(param_string(node, "representation"));
    if (!r) throw std::invalid_argument("gi.irradiance_volume '" + node.id + "': unknown representation");
    constants_ = {uint32_t(*r), param_bool(node, "visibility") ? 1u : 0u};
    push_ = {0, float(param_number(node, "normal_bias")), float(param_number(node, "view_bias")),
             resolution_divisor(node)};
    if (param_string(node, "mode") == "dynamic") {
      ProbeUpdateSettings update;
      update.probes_per_update = uint32_t(param_number(node, "probes_per_frame"));
      update.rays = uint32_t(param_number(node, "update_rays"));
      update.hysteresis = param_number(node, "hysteresis");
      update.placement_rays = settings_.rays;
      update.seed = settings_.seed;
      // Further bounces read the probes as this node's lookup does.
      update.lookup = {*r, constants_[1] != 0, push_.normal_bias, push_.view_bias};
      updater_.emplace(update, uint32_t(param_number(node, "settle_sweeps")));
    }
  }

  void record(PassContext& ctx) override {
    if (ctx.pass().pass == "lookup")
      lookup(ctx);
    else if (ctx.pass().pass == "upsample")
      upsample(ctx);
    else
      throw std::logic_error("gi.irradiance_volume has no pass '" + ctx.pass().pass + "'");
  }

  uint64_t probe_version() const override { return version_; }

  ProbeVolumeBinding probe_volume() override {
    return {probes_ ? &*probes_ : nullptr,
            push_.volume_count,
            constants_[0],
            constants_[1] != 0,
            push_.normal_bias,
            push_.view_bias,
            version_};
  }

  ProbeSnapshot probe_snapshot() const override {
    const std::vector<ProbeGrid>& grids = updater_ ? updater_->probes() : grids_;
    return {version_, updater_.has_value(), updater_ ? updater_->landed() : 0, whole_probe_file(grids, settings_)};
  }

 private:
  bool full_resolution() const { return push_.k == 1; }

  void lookup(PassContext& ctx) {
    prepare_probes(ctx);
    if (ctx.has("out.probes")) probes_->copy_volumes(ctx.cmd(), ctx.buffer("out.probes").handle());
    const Image& depth = ctx.image("in.gbuffer", 0);
    Image& target = ctx.image(full_resolution() ? "out.irradiance" : "tmp.lowres");
    camera_->write_value(camera_constants(ctx.scene().camera, depth.desc().width, depth.desc().height));
    const DescriptorWrite writes[] = {uniform_buffer(0, camera_->handle()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      uniform_buffer(3, probes_->volumes()),
                                      sampled_image(4, probes_->records().view(), ctx.nearest_sampler()),
                                      sampled_image(5, probes_->irradiance().view(), ctx.linear_sampler()),
                                      sampled_image(6, probes_->distance().view(), ctx.linear_sampler()),
                                      storage_image(7, target.view())};
    dispatch_compute(ctx, "nodes/gi/irradiance_volume/shaders/irradiance_volume.comp", writes, target.desc().width,
                     target.desc().height, std::as_bytes(std::span(&push_, 1)), kTileSize, constants_);
  }

  // One invocation per texel of lowres, each writing its block of k x k pixels. At full
  // resolution the lookup wrote the output itself, and there is nothing to do.
  void upsample(PassContext& ctx) {
    if (full_resolution()) return;
    Image& out = ctx.image("out.irradiance");
    Image& low = ctx.image("tmp.lowres");
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(3, out.view())};
    dispatch_compute(ctx, "nodes/gi/irradiance_volume/shaders/upsample.comp", writes, low.desc().width,
                     low.desc().height, std::as_bytes(std::span(&push_.k, 1)));
  }

  void prepare_probes(PassContext& ctx) {
    const SceneView& scene = ctx.scene();
    const uint64_t key = probe_bake_key(scene);
    if (!updater_) {
      if (!probes_ || baked_key_ != key) grids_ = bake(ctx, key);
      return;
    }
    const uint64_t volumes = probe_volume_key(scene);
    if (!camera_ || volume_key_ != volumes) {
      updater_->reset(bake(ctx, key));
      volume_key_ = volumes;
    } else if (const std::vector<ProbeGrid>* updated = updater_->finished()) {
      upload(ctx, *updated);
    }
    if (!updater_->in_flight()) updater_->start(scene, key, environment(ctx));
  }

  // The plan's environment for the CPU tracers, loaded once (per environment presence).
  std::shared_ptr<const PathEnvironment> environment(PassContext& ctx) {
    const bool has = ctx.scene().has_environment;
    if (!environment_ || environment_has_ != has) {
      const std::string who = "gi.irradiance_volume '" + ctx.node().id + "'";
      environment_ = std::make_shared<const PathEnvironment>(plan_environment(ctx.plan(), has, who.c_str()));
      environment_has_ = has;
    }
    return environment_;
  }

  // Bakes every volume of the frame's scene and uploads the probes.
  std::vector<ProbeGrid> bake(PassContext& ctx, uint64_t key) {
    const SceneView& scene = ctx.scene();
    const auto start = std::chrono::steady_clock::now();
    const PathScene traced(scene, *environment(ctx));
    std::vector<ProbeGrid> grids;
    for (const IrradianceVolumeData& volume : scene.irradiance_volumes) {
      ProbeGrid& grid = grids.emplace_back(volume);
      bake_probes(traced, grid, settings_, 0, grid.probe_count());
    }
    const size_t probes = upload(ctx, grids);
    baked_key_ = key;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr,
                 "gi.irradiance_volume '%s': baked %zu probes in %zu volume(s), %u rays, %u bounces, in %.2f s\n",
                 ctx.node().id.c_str(), probes, grids.size(), settings_.rays, settings_.bounces, seconds);
    return grids;
  }

  // Packs every volume's probes into the atlas and puts it on the device; returns how many.
  size_t upload(PassContext& ctx, std::span<const ProbeGrid> grids) {
    if (!camera_) {
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      probes_.emplace(ctx.gpu(), ctx.node().id);
    }
    ProbeAtlas atlas;
    try {
      atlas = pack_probe_atlas(grids, ctx.gpu().properties().limits.maxImageDimension2D);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("gi.irradiance_volume '" + ctx.node().id + "': " + e.what());
    }
    probes_->upload(ctx.cmd(), atlas);
    version_ = ++uploads;
    push_.volume_count = uint32_t(atlas.volumes.size());
    return size_t(atlas.probe_count);
  }

  ProbeBakeSettings settings_;
  Push push_{};
  std::array<uint32_t, 2> constants_{};  // shaders/irradiance_volume.comp: representation, visibility
  uint64_t baked_key_ = 0, volume_key_ = 0;
  std::optional<HostBuffer> camera_;
  std::optional<ProbeAtlasImages> probes_;
  std::shared_ptr<const PathEnvironment> environment_;
  bool environment_has_ = false;
  std::optional<ProbeUpdater> updater_;  // the dynamic mode's, which holds its probes
  std::vector<ProbeGrid> grids_;         // the static mode's probes, as uploaded
  uint64_t version_ = 0;                 // of the last upload
};

}  // namespace

std::unique_ptr<NodeKernel> make_irradiance_volume_kernel(const PlanNode& node) {
  return std::make_unique<IrradianceVolumeKernel>(node);
}

}  // namespace lg
