// The interface between the executor and the nodes: a NodeKernel records the commands of one
// plan node's passes, given a PassContext that binds the pass's slots ("in.color",
// "out.ao", "tmp.chain") to the images and buffers the plan placed for them. The executor knows
// kernels only through this interface and a KernelRegistry that the CLI and the editor fill from
// nodes/ (layers point downward: runtime/ never includes nodes/).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "graph/plan.h"

namespace lg {

class Buffer;
class Context;
class GpuScene;
class Image;
class NodeKernel;
class PipelineCache;
struct SceneView;

// What a kernel may use while recording one pass. The plan's barriers before the pass are
// already recorded; the kernel records only its own dispatches and draws.
class PassContext {
 public:
  virtual ~PassContext() = default;

  virtual Context& gpu() = 0;
  virtual PipelineCache& pipelines() = 0;
  virtual VkCommandBuffer cmd() = 0;

  virtual const Plan& plan() const = 0;
  virtual const PlanNode& node() const = 0;
  virtual const PlanPass& pass() const = 0;
  virtual uint64_t frame_index() const = 0;  // 0 on the first frame (history starts cleared)

  virtual const SceneView& scene() const = 0;
  virtual GpuScene& gpu_scene() = 0;  // the scene's meshes and textures on the device

  // Whether the pass touches `slot` (an optional input may be unlinked).
  virtual bool has(std::string_view slot, int component = 0) const = 0;
  // The image or buffer the plan placed for `slot` of this pass (component: within a bundle,
  // e.g. the G-buffer's normal is component 1). Throws naming the node, pass and slot when the
  // pass has no such access.
  virtual Image& image(std::string_view slot, int component = 0) = 0;
  virtual Buffer& buffer(std::string_view slot) = 0;
  // The kernel of the node whose output the pass's input `slot` reads, or null (no such input,
  // or a producer without passes): for a port whose producer keeps more on the device than the
  // plan's resource carries (gi.irradiance_volume's probe atlas behind its `probes` output). The
  // link orders the passes, so the producer recorded its passes of this frame already.
  virtual NodeKernel* producer(std::string_view slot) = 0;
  // Samplers kept by the executor: bilinear with clamped edges, and nearest.
  virtual VkSampler linear_sampler() = 0;
  virtual VkSampler nearest_sampler() = 0;
};

class NodeKernel {
 public:
  virtual ~NodeKernel() = default;
  // Records `pass.pass().pass` (a pass name of the node's schema). Throws on failure; the
  // executor adds the pass's name to the message.
  virtual void record(PassContext& pass) = 0;
  // Called when a frame has finished on the device: a kernel may free what only its recording
  // needed (env.load its file's copies once the cube they fill is a cached result). A static
  // pass recorded again later, its cache invalidated, must then rebuild what it freed.
  virtual void frame_finished() {}
};

// Makes the kernel of one plan node; the kernel lives as long as the executor's plan.
using KernelFactory = std::function<std::unique_ptr<NodeKernel>(const PlanNode& node)>;

class KernelRegistry {
 public:
  void add(std::string type, KernelFactory factory) { factories_[std::move(type)] = std::move(factory); }
  const KernelFactory* find(std::string_view type) const {
    auto it = factories_.find(type);
    return it == factories_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, KernelFactory, std::less<>> factories_;
};

}  // namespace lg
