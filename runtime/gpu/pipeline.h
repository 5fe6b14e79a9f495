// Compute and graphics pipelines (graphics with dynamic rendering: no render passes) made
// from SPIR-V and cached by a hash of the SPIR-V words and the pipeline state, so asking again
// for the same pipeline returns the one made before. Descriptors are push descriptors (set 0,
// VK_KHR_push_descriptor): no pools, no descriptor indexing (lavapipe has none).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace lg {

class Context;

// One binding of set 0, visible to every stage of the pipeline.
struct DescriptorBinding {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  uint32_t count = 1;
};

struct ComputePipelineDesc {
  std::string name{};  // in validation messages
  std::span<const uint32_t> shader{};
  std::vector<DescriptorBinding> bindings{};
  uint32_t push_constant_bytes = 0;
  // Specialization constants, 32 bits each: constant_id i takes constants[i]. The driver folds
  // them like literals, so branches on them cost nothing (lavapipe runs both sides of a branch on
  // a uniform value, masked, but drops a folded one).
  std::vector<uint32_t> constants{};
};

// additive: src + dst; alpha: src x src alpha + dst x (1 - src alpha); premultiplied: src +
// dst x (1 - src alpha), for colours already multiplied by their alpha ("over").
enum class Blend : uint8_t { none, additive, alpha, premultiplied };

struct GraphicsPipelineDesc {
  std::string name{};
  std::span<const uint32_t> vertex_shader{}, fragment_shader{};
  std::vector<DescriptorBinding> bindings{};
  uint32_t push_constant_bytes = 0;
  std::vector<VkVertexInputBindingDescription> vertex_bindings{};  // empty: vertices come from the shader
  std::vector<VkVertexInputAttributeDescription> vertex_attributes{};
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  std::vector<VkFormat> color_formats{};
  Blend blend = Blend::none;  // the same for every colour attachment
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  bool depth_test = false, depth_write = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reversed Z
};

struct Pipeline {
  VkPipeline handle = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;  // set 0, push descriptors
  VkPipelineBindPoint bind_point = VK_PIPELINE_BIND_POINT_COMPUTE;
  VkShaderStageFlags stages = 0;  // of the bindings and push constants
  uint32_t push_constant_bytes = 0;
};

// Graphics pipelines take viewport and scissor as dynamic state: the whole target's.
void set_viewport(VkCommandBuffer cmd, uint32_t width, uint32_t height);

// A render target of dynamic rendering, in ATTACHMENT_OPTIMAL, cleared to `clear` and stored.
VkRenderingAttachmentInfo cleared_attachment(VkImageView view, VkClearValue clear = {});

// Dynamic rendering over the whole width x height target, one layer, into `colors` and an
// optional depth attachment; the info points at them, so they must outlive it.
VkRenderingInfo rendering_info(uint32_t width, uint32_t height, std::span<const VkRenderingAttachmentInfo> colors,
                               const VkRenderingAttachmentInfo* depth = nullptr);

class PipelineCache {
 public:
  explicit PipelineCache(Context& context);
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // The pipeline for `desc`, made on first request. References stay valid while the cache lives.
  const Pipeline& compute(const ComputePipelineDesc& desc);
  const Pipeline& graphics(const GraphicsPipelineDesc& desc);

  size_t size() const { return pipelines_.size(); }

 private:
  Context& context_;
  // Keyed by the SPIR-V and state bytes; the map hashes them and compares them in full.
  std::unordered_map<std::string, Pipeline> pipelines_;
};

}  // namespace lg
