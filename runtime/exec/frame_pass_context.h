// The PassContext the executor hands a kernel while recording one pass: the pass's slots
// bound to the images and buffers placed for them this frame.
#pragma once

#include <memory>
#include <span>

#include "runtime/exec/node_kernel.h"
#include "runtime/exec/plan_memory.h"

namespace lg {

class Sampler;

// What every pass of a frame shares.
struct FrameResources {
  Context& context;
  PipelineCache& pipelines;
  VkCommandBuffer cmd;
  const Plan& plan;
  std::vector<PlacedResource>& resources;
  const Sampler& linear;
  const Sampler& nearest;
  uint64_t frame_index;
  const SceneView& scene;
  GpuScene& gpu_scene;
  std::span<const std::unique_ptr<NodeKernel>> kernels;  // per plan node; null without passes
};

class FramePassContext final : public PassContext {
 public:
  FramePassContext(const FrameResources& frame, const PlanPass& pass) : frame_(frame), pass_(pass) {}

  Context& gpu() override { return frame_.context; }
  PipelineCache& pipelines() override { return frame_.pipelines; }
  VkCommandBuffer cmd() override { return frame_.cmd; }
  const Plan& plan() const override { return frame_.plan; }
  const PlanNode& node() const override { return frame_.plan.nodes[pass_.node]; }
  const PlanPass& pass() const override { return pass_; }
  uint64_t frame_index() const override { return frame_.frame_index; }
  const SceneView& scene() const override { return frame_.scene; }
  GpuScene& gpu_scene() override { return frame_.gpu_scene; }

  bool has(std::string_view slot, int component) const override;
  Image& image(std::string_view slot, int component) override;
  Buffer& buffer(std::string_view slot) override;
  NodeKernel* producer(std::string_view slot) override;
  VkSampler linear_sampler() override;
  VkSampler nearest_sampler() override;

 private:
  const PlanAccess* find(std::string_view slot, int component) const;
  [[noreturn]] void missing(std::string_view slot, int component, std::string_view what) const;

  const FrameResources& frame_;
  const PlanPass& pass_;
};

}  // namespace lg
