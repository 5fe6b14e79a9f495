#include "runtime/exec/executor.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "runtime/exec/executor_error.h"
#include "runtime/exec/frame_pass_context.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/scene/camera_jitter.h"

namespace lg {
namespace {

std::string names_of(const Plan& plan) {
  std::string out;
  for (const PlanResource& r : plan.resources) out += (out.empty() ? "" : ", ") + r.desc.name;
  return out;
}

// The "name" param of an output node, as output.display has it.
std::string output_name(const PlanNode& node) {
  const JsonValue* name = node.params.find("name");
  return name && name->is_string() ? name->as_string() : "main";
}

}  // namespace

Executor::Executor(Context& context, const KernelRegistry& kernels, Plan plan)
    : context_(context),
      registry_(kernels),
      plan_(std::move(plan)),
      submitter_(context),
      linear_(context, {Filter::linear, Address::clamp}),
      nearest_(context, {Filter::nearest, Address::clamp}),
      timestamps_(context, static_cast<uint32_t>(plan_.passes.size()) + 1),
      layouts_(layouts_after_frame(plan_)),
      ran_keys_(plan_.passes.size(), 0) {
  // Kernels first: a missing one is a configuration error, found before any memory is taken.
  make_kernels();
  memory_ = allocate_plan_memory(context, plan_);
}

void Executor::make_kernels() {
  std::vector<std::unique_ptr<NodeKernel>> kernels(plan_.nodes.size());
  for (const PlanPass& pass : plan_.passes) {
    auto& kernel = kernels[pass.node];
    if (kernel) continue;
    const PlanNode& node = plan_.nodes[pass.node];
    const KernelFactory* factory = registry_.find(node.type);
    if (!factory) throw ExecutorError("node '" + node.id + "' (" + node.type + ") has no kernel in this build");
    kernel = (*factory)(node);
    if (!kernel) throw ExecutorError("the kernel factory of " + node.type + " made nothing for node '" + node.id + "'");
  }
  kernels_ = std::move(kernels);
}

Executor::~Executor() = default;

PipelineCache& Executor::pipelines() {
  return context_.pipelines();
}

void Executor::invalidate_cache() {
  std::fill(ran_keys_.begin(), ran_keys_.end(), 0);
}

// Static passes run as a whole or not at all: a partial run would find the cached images in
// their readers' layouts, not in the layouts the plan's barriers before static passes expect.
bool Executor::caches_valid() const {
  bool any = false;
  for (size_t p = 0; p < plan_.passes.size(); ++p) {
    if (!plan_.passes[p].is_static) continue;
    if (ran_keys_[p] != plan_.passes[p].cache_key) return false;
    any = true;
  }
  return any;
}

// Swapping which image backs which half (no copy): X's image, written last frame, becomes
// X@previous, and X gets the older bytes to overwrite. Both halves are persistent (block 1)
// and alike, and X@previous expects exactly the layout X's image ends the frame in.
void Executor::swap_history() {
  for (size_t r = 0; r < plan_.resources.size(); ++r)
    if (int current = plan_.resources[r].desc.history_of; current >= 0)
      std::swap(memory_.resources[r], memory_.resources[current]);
}

// The first frame's history reads cleared images (zeros), in the layout their current half
// ends a frame in, which is what the plan's history barriers name as their old layout.
void Executor::clear_history(VkCommandBuffer cmd) {
  const VkClearColorValue zero_color{};
  const VkClearDepthStencilValue zero_depth{};
  for (size_t r = 0; r < plan_.resources.size(); ++r) {
    const int current = plan_.resources[r].desc.history_of;
    if (current < 0) continue;
    PlacedResource& placed = memory_.resources[r];
    if (auto* buffer = std::get_if<Buffer>(&placed)) {
      vkCmdFillBuffer(cmd, buffer->handle(), 0, VK_WHOLE_SIZE, 0);
      memory_barrier(cmd);
    } else if (auto* image = std::get_if<Image>(&placed)) {
      image_barrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      const VkImageSubresourceRange range = image->whole_range();
      if (format_info(image->desc().format).depth)
        vkCmdClearDepthStencilImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL, &zero_depth, 1, &range);
      else
        vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL, &zero_color, 1, &range);
      image_barrier(cmd, *image, VK_IMAGE_LAYOUT_GENERAL, vk_layout(layouts_[current]));
    }
  }
}

FrameStats Executor::run_frame(const SceneView& host_scene, GpuScene& gpu_scene) {
  // A copy only for a jittered frame: the host's view (and what it keeps as last frame's
  // camera) stays unjittered.
  std::optional<SceneView> jittered;
  if (plan_.jitter_grid[0] > 0 && !host_scene.camera.jitter) {
    jittered.emplace(host_scene);
    jittered->camera.jitter = jitter_ndc(frame_jitter_pixels(frames_), plan_.jitter_grid[0], plan_.jitter_grid[1]);
  }
  const SceneView& scene = jittered ? *jittered : host_scene;
  gpu_scene.update(scene);
  const auto start = std::chrono::steady_clock::now();
  if (frames_ > 0) swap_history();
  const bool skip_cached = caches_valid();
  try {
    submitter_.run([&](VkCommandBuffer cmd) { record_frame(cmd, scene, gpu_scene, skip_cached); });
  } catch (...) {
    if (frames_ > 0) swap_history();  // back: the failed frame does not count
    // Its kernels may believe their uploads and layout changes ran: they start afresh, and the
    // static passes run again. A frame that timed out may still be running on the device, so
    // the old kernels' resources go only once it is idle (or lost).
    vkDeviceWaitIdle(context_.device());
    make_kernels();
    invalidate_cache();
    throw;
  }
  const auto end = std::chrono::steady_clock::now();

  FrameStats stats = plan_stats(plan_);
  stats.frame = frames_;
  stats.cpu_ms = std::chrono::duration<double, std::milli>(end - start).count();
  const std::vector<ScopeTime> times = timestamps_.results();  // [0]: the whole frame
  stats.gpu_ms = times.at(0).milliseconds;
  size_t scope = 1;
  for (size_t p = 0; p < plan_.passes.size(); ++p) {
    const PlanPass& pass = plan_.passes[p];
    const bool cached = skip_cached && pass.is_static;
    stats.passes.push_back({pass.name, cached ? 0.0 : times.at(scope++).milliseconds, cached});
    if (pass.is_static) ran_keys_[p] = pass.cache_key;
  }
  stats.device_memory_used = context_.device_memory_used();
  for (auto& kernel : kernels_)
    if (kernel) kernel->frame_finished();
  ++frames_;
  return stats;
}

void Executor::record_frame(VkCommandBuffer cmd, const SceneView& scene, GpuScene& gpu_scene, bool skip_cached) {
  timestamps_.reset(cmd);
  const uint32_t whole = timestamps_.begin(cmd, "frame");
  if (frames_ == 0) clear_history(cmd);
  const FrameResources frame{
      context_, context_.pipelines(), cmd, plan_, memory_.resources, linear_, nearest_, frames_, scene, gpu_scene,
      kernels_};
  BarrierBatch batch;
  size_t next_barrier = 0;
  for (size_t p = 0; p < plan_.passes.size(); ++p) {
    const PlanPass& pass = plan_.passes[p];
    const bool skip = skip_cached && pass.is_static;
    for (; next_barrier < plan_.barriers.size() && plan_.barriers[next_barrier].before == static_cast<int>(p);
         ++next_barrier) {
      const Barrier& b = plan_.barriers[next_barrier];
      if (skip || (skip_cached && b.skip_when_cached)) continue;
      const PlacedResource& r = memory_.resources[b.resource];
      if (auto* image = std::get_if<Image>(&r))
        batch.add(b, *image);
      else
        batch.add(b, std::get<Buffer>(r));
    }
    batch.record(cmd);
    if (skip) continue;
    const uint32_t scope = timestamps_.begin(cmd, pass.name);
    FramePassContext context(frame, pass);
    try {
      kernels_[pass.node]->record(context);
    } catch (const std::exception& e) {
      throw ExecutorError("pass '" + pass.name + "': " + e.what());
    }
    timestamps_.end(cmd, scope);
  }
  timestamps_.end(cmd, whole);
}

int Executor::resource_index(std::string_view name) const {
  for (size_t r = 0; r < plan_.resources.size(); ++r)
    if (plan_.resources[r].desc.name == name) return static_cast<int>(r);
  throw ExecutorError("the plan has no resource '" + std::string(name) + "'; it has " + names_of(plan_));
}

Image& Executor::image(std::string_view resource) {
  if (auto* image = std::get_if<Image>(&memory_.resources[resource_index(resource)])) return *image;
  throw ExecutorError("'" + std::string(resource) + "' is not an image on the device (a buffer, or no pass uses it)");
}

Buffer& Executor::buffer(std::string_view resource) {
  if (auto* buffer = std::get_if<Buffer>(&memory_.resources[resource_index(resource)])) return *buffer;
  throw ExecutorError("'" + std::string(resource) + "' is not a buffer on the device (an image, or no pass uses it)");
}

VkImageLayout Executor::layout(std::string_view resource) const {
  return frames_ == 0 ? VK_IMAGE_LAYOUT_UNDEFINED : vk_layout(layouts_[resource_index(resource)]);
}

const PlacedResource& Executor::readable(std::string_view resource) const {
  const int r = resource_index(resource);
  if (frames_ == 0) throw ExecutorError("cannot read '" + std::string(resource) + "': no frame has run yet");
  if (bytes_taken_over(plan_, r))
    throw ExecutorError("cannot read '" + std::string(resource) +
                        "': later passes of the frame reuse its memory (compile without aliasing to read it)");
  return memory_.resources[r];
}

std::vector<float> Executor::read_image(std::string_view resource, ImageLocation where) {
  const auto* image = std::get_if<Image>(&readable(resource));
  if (!image) throw ExecutorError("'" + std::string(resource) + "' is not an image on the device");
  return lg::read_image(submitter_, *image, layout(resource), where);
}

std::vector<std::byte> Executor::read_buffer(std::string_view resource) {
  const auto* buffer = std::get_if<Buffer>(&readable(resource));
  if (!buffer) throw ExecutorError("'" + std::string(resource) + "' is not a buffer on the device");
  return lg::read_buffer(submitter_, *buffer);
}

std::vector<std::string> Executor::readable_resources() const {
  std::vector<std::string> out;
  for (size_t r = 0; r < plan_.resources.size(); ++r)
    if (plan_.resources[r].first >= 0 && !bytes_taken_over(plan_, static_cast<int>(r)))
      out.push_back(plan_.resources[r].desc.name);
  return out;
}

std::vector<std::string> Executor::output_names() const {
  std::vector<std::string> out;
  for (const PlanOutput& o : plan_.outputs)
    if (o.node >= 0 && !o.resources.empty()) out.push_back(output_name(plan_.nodes[o.node]));
  return out;
}

const std::string& Executor::output_resource(std::string_view name) const {
  for (const PlanOutput& o : plan_.outputs)
    if (o.node >= 0 && !o.resources.empty() && output_name(plan_.nodes[o.node]) == name)
      return plan_.resources[o.resources.front()].desc.name;
  std::string known;
  for (const std::string& n : output_names()) known += (known.empty() ? "'" : ", '") + n + "'";
  throw ExecutorError("no output node is named '" + std::string(name) + "'; the plan has " +
                      (known.empty() ? "none" : known));
}

}  // namespace lg
