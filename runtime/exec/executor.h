// Runs a Plan on the GPU, frame after frame. At construction it allocates the plan's memory
// blocks, creates every image and buffer at its placement and makes one kernel per node with
// passes. Each frame is one command buffer: per pass in schedule order, the plan's barriers
// before it in one batch, timestamps around it and its kernel's commands; then submit and wait.
// History pairs (X and X@previous) swap images each frame; static passes whose cache keys are
// unchanged since they ran are skipped with their barriers. Between frames any resource can be
// read back by name, and the results of output nodes by their names.
//
// Layouts between frames: every image is in the layout of its last use in the frame (GENERAL
// after storage use, READ_ONLY_OPTIMAL after sampling, ATTACHMENT_OPTIMAL after rendering);
// layout() says which. A host sampling an image between frames must leave it in that layout.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/plan.h"
#include "runtime/exec/frame_stats.h"
#include "runtime/exec/node_kernel.h"
#include "runtime/exec/plan_memory.h"
#include "runtime/exec/static_results_file.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/submit.h"
#include "runtime/gpu/timestamps.h"
#include "runtime/gpu/transfer.h"

namespace lg {

class Executor {
 public:
  // `plan` must be compiled with `options.alias = device_alias_options(context)` so that its
  // placements hold what the device needs. Throws ExecutorError naming the node and its type
  // when a node with passes has no kernel in `kernels`. Works the same on a Context of its own
  // or one adopted from a host engine. `kernels` must outlive the executor (a failed frame makes
  // its kernels again).
  Executor(Context& context, const KernelRegistry& kernels, Plan plan);
  ~Executor();
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  const Plan& plan() const { return plan_; }
  Context& context() const { return context_; }
  // For uploads and readbacks between frames (a GpuScene may share it); never during one.
  Submitter& submitter() { return submitter_; }
  PipelineCache& pipelines();  // the context's, which every executor on it shares

  // Updates `gpu_scene` from `scene`, then records, submits and waits for one frame; a wait
  // past the submit timeout throws GpuError. A kernel's failure throws ExecutorError naming
  // the pass, and the frame does not count (history and caches stay as they were). When the
  // plan has a jitter grid and the scene's camera no jitter of its own, the frame's passes see
  // the camera jittered by frame_jitter_pixels(frames_run()) on that grid (camera_jitter.h).
  FrameStats run_frame(const SceneView& scene, GpuScene& gpu_scene);
  uint64_t frames_run() const { return frames_; }
  // The kernel of plan node `node` (an index into plan().nodes), for tools that ask a kernel
  // about its state between frames; null for a node without passes.
  NodeKernel* kernel(size_t node) const { return node < kernels_.size() ? kernels_[node].get() : nullptr; }
  // The next frame runs every static pass again.
  void invalidate_cache();
  // Takes the results of static passes from `previous`, an executor of an earlier plan (the same
  // graph recompiled after an edit or for another frame size), where this plan would compute
  // them again with the same cache keys: the next frame skips them. All or nothing, as caching
  // is: false, and nothing taken, unless every static pass of this plan ran in `previous` with
  // its key and wrote resources of the same name and description there. Copies on the GPU.
  bool adopt_cached_results(Executor& previous);
  // The bytes of every cached resource, in plan order, for keeping on disk (static_results_store.h);
  // empty unless the static passes have run (or their results were taken) with this plan's keys.
  std::vector<StoredResult> read_cached_results();
  // Takes such results (before the first frame): the next frame skips the static passes. All or
  // nothing: when they do not match this plan's cached resources by name and size, nothing is
  // taken and the reason is returned; empty when taken.
  std::string load_cached_results(std::span<const StoredResult> results);

  // Resources by name ("bloom.color", "gtao.ao@previous", "bloom/chain"), between frames.
  // Unknown names throw ExecutorError listing the known ones. After frame N, X holds what
  // frame N wrote and X@previous what frame N-1 wrote. An Image stays valid until the next
  // run_frame (history halves trade images then).
  int resource_index(std::string_view name) const;
  Image& image(std::string_view resource);
  Buffer& buffer(std::string_view resource);
  VkImageLayout layout(std::string_view resource) const;  // after the last frame
  // Float RGBA per mip and layer (transfer.h). Throws ExecutorError before the first frame and
  // for a transient resource whose bytes a later resource of the frame takes over (compile
  // without aliasing to read those).
  std::vector<float> read_image(std::string_view resource, ImageLocation where = {});
  std::vector<std::byte> read_buffer(std::string_view resource);
  // The resources those two can read after a frame, in plan order (for `render --dump DIR`).
  std::vector<std::string> readable_resources() const;

  // Results of output nodes (output.display) by their "name" param ("main" by default).
  std::vector<std::string> output_names() const;
  // The resource feeding that output node; unknown names throw ExecutorError listing the known.
  const std::string& output_resource(std::string_view output_name) const;
  Image& output_image(std::string_view output_name) { return image(output_resource(output_name)); }

 private:
  // One kernel per node with passes, made afresh (all or none: on a throw the old ones stay).
  void make_kernels();
  void record_frame(VkCommandBuffer cmd, const SceneView& scene, GpuScene& gpu_scene, bool skip_cached);
  void clear_history(VkCommandBuffer cmd);
  void swap_history();
  bool caches_valid() const;
  std::vector<int> stored_resources() const;  // the cached resources with memory, in plan order
  const PlacedResource& readable(std::string_view resource) const;

  Context& context_;
  const KernelRegistry& registry_;  // outlives the executor
  Plan plan_;
  Submitter submitter_;
  Sampler linear_, nearest_;
  TimestampQueries timestamps_;
  PlanMemory memory_;
  std::vector<Layout> layouts_;                       // per resource, between frames
  std::vector<std::unique_ptr<NodeKernel>> kernels_;  // per plan node; null without passes
  std::vector<uint64_t> ran_keys_;                    // per pass: the cache key it last ran with
  uint64_t frames_ = 0;
};

}  // namespace lg
