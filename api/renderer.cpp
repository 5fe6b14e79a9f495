#include "api/renderer.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "api/static_results_identity.h"
#include "graph/graph_io.h"
#include "nodes/builtin_kernels.h"
#include "nodes/builtin_schemas.h"
#include "runtime/exec/executor_error.h"
#include "runtime/gpu/plan_resources.h"
#include "runtime/scene/camera_jitter.h"
#include "runtime/scene/make_scene_view.h"

namespace lg {
namespace {

bool ran_static_passes(const Plan& plan, const FrameStats& stats) {
  for (size_t p = 0; p < plan.passes.size(); ++p)
    if (plan.passes[p].is_static && !stats.passes[p].cached) return true;
  return false;
}

}  // namespace

Renderer::Renderer(const RendererOptions& options)
    : options_(options),
      context_(options.host ? std::make_unique<Context>(*options.host) : std::make_unique<Context>(options.device)) {
  const std::string folder =
      options.pipeline_cache_folder.empty() ? default_pipeline_cache_folder() : options.pipeline_cache_folder;
  if (options.pipeline_cache_on_disk && !pipeline_cache_disabled_by_environment() && !folder.empty()) {
    pipeline_store_ = std::make_unique<PipelineCacheStore>(*context_, folder);
    static_store_ = std::make_unique<StaticResultsStore>(
        folder, StaticResultsIdentity{device_identity(context_->properties()), node_code_identity()},
        options.static_results_max_bytes);
  }
}

Renderer::~Renderer() {
  if (pipeline_store_) pipeline_store_->save();  // never throws; its warning has no reader now
}

std::vector<std::string> Renderer::take_warnings() {
  if (!pipeline_store_) return {};
  std::vector<std::string> warnings = pipeline_store_->take_warnings();
  for (std::string& w : static_store_->take_warnings()) warnings.push_back(std::move(w));
  return warnings;
}

void Renderer::load_graph(const std::string& path) {
  Diagnostics diagnostics(path);
  std::optional<Graph> graph = load_graph_file(path, diagnostics);
  if (!graph) throw GraphError(diagnostics.to_string());
  set_graph(std::move(*graph));
}

void Renderer::set_graph(Graph graph) {
  graph_ = std::move(graph);
  graph_changed_ = true;
}

void Renderer::reload_graph() {
  if (!graph_ || graph_->file.empty()) throw GraphError("no graph file was loaded, so there is nothing to reload");
  load_graph(graph_->file);
}

void Renderer::compile_for(const SceneSummary& summary, FrameSize frame) {
  if (!graph_) throw GraphError("no graph loaded: call load_graph() before render()");
  Diagnostics diagnostics(graph_->file);
  CompileOptions options;
  options.scene = summary;
  options.frame = frame;
  options.roots = options_.asset_roots;
  options.alias = device_alias_options(*context_);
  options.alias.enabled = options_.alias;
  options.keep_optional_outputs = options_.keep_optional_outputs;
  CompileResult result = compile(*graph_, builtin_registry(), options, diagnostics);
  if (!result.plan) {
    diagnostics.sort_by_position();
    throw GraphError(diagnostics.to_string());
  }
  // The new executor is built before the old one goes, so a failure leaves the last good one;
  // static results the new plan would compute again with the same keys are carried over.
  auto executor = std::make_unique<Executor>(*context_, builtin_kernels(), std::move(*result.plan));
  // Else from the disk, whose key hashes the input files' contents: not read for results carried
  // over, which are never saved again either.
  const bool adopted = executor_ && executor->adopt_cached_results(*executor_);
  const uint64_t static_key =
      static_store_ && !adopted
          ? static_store_->key_for(executor->plan(), static_input_files(executor->plan(), builtin_registry()))
          : 0;
  if (static_key) static_store_->load(*executor, static_key);
  if (!gpu_scene_) gpu_scene_ = std::make_unique<GpuScene>(*context_);
  executor_ = std::move(executor);
  static_key_ = static_key;
#if defined(__GLIBC__)
  // The old executor's memory, and what the driver freed with it, goes back to the system:
  // glibc keeps freed heap pages resident, and the soak saw them add up (docs/reliability.md).
  malloc_trim(0);
#endif
  summary_ = summary;
  frame_ = frame;
  graph_changed_ = false;
}

const FrameStats& Renderer::render(const World& world, FrameSize frame, FrameTiming timing) {
  SceneView view = make_scene_view(world, float(frame.width) / float(frame.height), has_view_ ? &view_ : nullptr);
  view.frame_seconds = timing.seconds;
  view.camera_cut = timing.camera_cut;
  if (timing.jitter) view.camera.jitter = jitter_ndc(*timing.jitter, frame.width, frame.height);
  const SceneSummary summary = view.summary();
  const bool compile = !executor_ || graph_changed_ || !summary_ || !(*summary_ == summary) || !(frame_ == frame);
  if (compile) compile_for(summary, frame);
  stats_ = executor_->run_frame(view, *gpu_scene_);
  // A new plan's first frame made whatever pipelines it needs: keep them for the next run now,
  // not only at shutdown, which a crash or a killed editor never reaches.
  // Static results too, when this frame computed them; not when the folder just refused the
  // pipeline cache (one warning for it).
  if (compile && pipeline_store_ && pipeline_store_->save() && ran_static_passes(executor_->plan(), stats_))
    static_store_->save(*executor_, static_key_);
  view_ = std::move(view);
  has_view_ = true;
  return stats_;
}

const Plan& Renderer::plan() const {
  if (!executor_) throw ExecutorError("no frame has been rendered yet, so there is no plan");
  return executor_->plan();
}

Executor& Renderer::executor() {
  if (!executor_) throw ExecutorError("no frame has been rendered yet, so there is no executor");
  return *executor_;
}

Image& Renderer::output_image(std::string_view name) {
  return executor().output_image(name);
}

VkImageLayout Renderer::output_layout(std::string_view name) {
  return executor().layout(executor().output_resource(name));
}

std::vector<float> Renderer::read_output(std::string_view name) {
  return executor().read_image(executor().output_resource(name));
}

}  // namespace lg
