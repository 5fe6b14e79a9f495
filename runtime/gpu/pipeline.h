// Compute and graphics pipelines (graphics with dynamic rendering: no render passes) made
// from SPIR-V and cached by a hash of the SPIR-V words and the pipeline state, so asking again
// for the same pipeline returns the one made before. Pipelines are made through a
// VkPipelineCache whose data can be saved and handed to a later run (pipeline_cache_store.h).
// Descriptors are push descriptors (set 0, VK_KHR_push_descriptor): no pools, no descriptor
// indexing (lavapipe has none).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <mutex>
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
  // The fragment stage's specialization constants, as ComputePipelineDesc::constants.
  std::vector<uint32_t> fragment_constants{};
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

// Context::pipelines() is the one every executor of a context shares, so a hot reload, a resize
// or a recompile finds the pipelines the last plan made. Safe to call from several threads.
class PipelineCache {
 public:
  explicit PipelineCache(Context& context);
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // The pipeline for `desc`, made on first request. References stay valid while the cache lives.
  const Pipeline& compute(const ComputePipelineDesc& desc);
  const Pipeline& graphics(const GraphicsPipelineDesc& desc);

  size_t size() const;
  // Pipelines made so far (vkCreate*Pipelines calls that succeeded).
  uint64_t created() const;
  // Of those, the ones the driver reports it made from its pipeline cache (creation feedback's
  // APPLICATION_PIPELINE_CACHE_HIT). A driver without a real cache, lavapipe among them, says 0.
  uint64_t driver_cache_hits() const;

  // The driver's cache data (vkGetPipelineCacheData): what a later run can merge().
  std::vector<std::byte> driver_data() const;
  // Adds data from driver_data() of an earlier run to the driver's cache. False when the driver
  // refuses it (then nothing changes); the data must be checked first (pipeline_cache_file.h).
  bool merge(std::span<const std::byte> driver_data);

 private:
  template <typename Create>
  const Pipeline& find_or_make(std::string key, Create&& create);

  Context& context_;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
  mutable std::mutex mutex_;
  // Keyed by the SPIR-V and state bytes; the map hashes them and compares them in full.
  std::unordered_map<std::string, Pipeline> pipelines_;
  uint64_t created_ = 0, driver_cache_hits_ = 0;
};

}  // namespace lg
