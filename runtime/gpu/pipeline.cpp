#include "runtime/gpu/pipeline.h"

#include <mutex>
#include <type_traits>

#include "graph/fault_injection.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

// The cache key: every input of pipeline creation, as bytes.
class Key {
 public:
  template <typename T>
  Key& add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    return *this;
  }
  template <typename T>
  Key& add_all(std::span<const T> values) {
    add(values.size());
    for (const T& v : values) add(v);
    return *this;
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

void add_layout(Key& key, const std::vector<DescriptorBinding>& bindings, uint32_t push_constant_bytes) {
  key.add(bindings.size());
  for (const auto& b : bindings) key.add(b.binding).add(b.type).add(b.count);
  key.add(push_constant_bytes);
}

void check_spirv(std::span<const uint32_t> words, const std::string& pipeline, const char* stage) {
  if (words.size() < 5 || words[0] != 0x07230203)
    throw GpuError("pipeline '" + pipeline + "': the " + stage + " shader is not SPIR-V");
}

class ShaderModule {
 public:
  ShaderModule(const Context& context, std::span<const uint32_t> words) : device_(context.device()) {
    auto info = vk_struct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    vk_check(inject_fault(FaultSite::shader_module) ? VK_ERROR_OUT_OF_HOST_MEMORY
                                                    : vkCreateShaderModule(device_, &info, nullptr, &module_),
             "vkCreateShaderModule");
  }
  ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  VkShaderModule handle() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

// Set 0 (push descriptors) and the push constant range; the pipeline itself is made by the caller.
Pipeline make_layout(const Context& context, const std::vector<DescriptorBinding>& bindings,
                     uint32_t push_constant_bytes, VkShaderStageFlags stages, VkPipelineBindPoint bind_point) {
  Pipeline p;
  p.bind_point = bind_point;
  p.stages = stages;
  p.push_constant_bytes = push_constant_bytes;
  std::vector<VkDescriptorSetLayoutBinding> vk_bindings;
  for (const auto& b : bindings) vk_bindings.push_back({b.binding, b.type, b.count, stages, nullptr});
  auto set = vk_struct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  set.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  set.bindingCount = static_cast<uint32_t>(vk_bindings.size());
  set.pBindings = vk_bindings.data();
  vk_check(vkCreateDescriptorSetLayout(context.device(), &set, nullptr, &p.set_layout), "vkCreateDescriptorSetLayout");

  VkPushConstantRange range{stages, 0, push_constant_bytes};
  auto layout = vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout.setLayoutCount = 1;
  layout.pSetLayouts = &p.set_layout;
  layout.pushConstantRangeCount = push_constant_bytes ? 1 : 0;
  layout.pPushConstantRanges = &range;
  VkResult r = vkCreatePipelineLayout(context.device(), &layout, nullptr, &p.layout);
  if (r != VK_SUCCESS) vkDestroyDescriptorSetLayout(context.device(), p.set_layout, nullptr);
  vk_check(r, "vkCreatePipelineLayout");
  return p;
}

void destroy(const Context& context, Pipeline& p) {
  vkDestroyPipeline(context.device(), p.handle, nullptr);
  vkDestroyPipelineLayout(context.device(), p.layout, nullptr);
  vkDestroyDescriptorSetLayout(context.device(), p.set_layout, nullptr);
}

// Where the driver says whether it made a pipeline from its cache; chained into the create info.
class CreationFeedback {
 public:
  VkPipelineCreationFeedbackCreateInfo* chain(uint32_t stages) {
    info_ = vk_struct<VkPipelineCreationFeedbackCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CREATION_FEEDBACK_CREATE_INFO);
    info_.pPipelineCreationFeedback = &pipeline_;
    info_.pipelineStageCreationFeedbackCount = stages;  // the validation layer wants one per stage
    info_.pPipelineStageCreationFeedbacks = stage_feedback_;
    return &info_;
  }
  bool cache_hit() const {
    const VkPipelineCreationFeedbackFlags hit =
        VK_PIPELINE_CREATION_FEEDBACK_VALID_BIT | VK_PIPELINE_CREATION_FEEDBACK_APPLICATION_PIPELINE_CACHE_HIT_BIT;
    return (pipeline_.flags & hit) == hit;
  }

 private:
  VkPipelineCreationFeedbackCreateInfo info_{};
  VkPipelineCreationFeedback pipeline_{}, stage_feedback_[2]{};
};

// Makes the pipeline with `create`, or cleans up the layout and rethrows.
template <typename Create>
Pipeline finish(const Context& context, Pipeline p, const std::string& name, Create&& create) {
  try {
    create(p);
  } catch (...) {
    destroy(context, p);
    throw;
  }
  context.set_name(VK_OBJECT_TYPE_PIPELINE, p.handle, name);
  return p;
}

// Specialization constants of 32 bits each: constant_id i at offset 4 i.
std::vector<VkSpecializationMapEntry> constant_entries(std::span<const uint32_t> constants) {
  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < constants.size(); ++i)
    entries.push_back({i, uint32_t(i * sizeof(uint32_t)), sizeof(uint32_t)});
  return entries;
}

VkSpecializationInfo specialization_info(std::span<const VkSpecializationMapEntry> entries,
                                         std::span<const uint32_t> constants) {
  return {uint32_t(entries.size()), entries.data(), constants.size_bytes(), constants.data()};
}

}  // namespace

void set_viewport(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
  const VkViewport viewport{0, 0, float(width), float(height), 0, 1};
  const VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

VkRenderingInfo rendering_info(uint32_t width, uint32_t height, std::span<const VkRenderingAttachmentInfo> colors,
                               const VkRenderingAttachmentInfo* depth) {
  auto info = vk_struct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = {{0, 0}, {width, height}};
  info.layerCount = 1;
  info.colorAttachmentCount = static_cast<uint32_t>(colors.size());
  info.pColorAttachments = colors.data();
  info.pDepthAttachment = depth;
  return info;
}

VkRenderingAttachmentInfo cleared_attachment(VkImageView view, VkClearValue clear) {
  auto a = vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  a.imageView = view;
  a.imageLayout = VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = clear;
  return a;
}

PipelineCache::PipelineCache(Context& context) : context_(context) {
  auto info = vk_struct<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  vk_check(vkCreatePipelineCache(context_.device(), &info, nullptr, &cache_), "vkCreatePipelineCache");
}

PipelineCache::~PipelineCache() {
  for (auto& [key, pipeline] : pipelines_) destroy(context_, pipeline);
  vkDestroyPipelineCache(context_.device(), cache_, nullptr);
}

size_t PipelineCache::size() const {
  std::lock_guard lock(mutex_);
  return pipelines_.size();
}

uint64_t PipelineCache::created() const {
  std::lock_guard lock(mutex_);
  return created_;
}

uint64_t PipelineCache::driver_cache_hits() const {
  std::lock_guard lock(mutex_);
  return driver_cache_hits_;
}

std::vector<std::byte> PipelineCache::driver_data() const {
  std::lock_guard lock(mutex_);
  std::vector<std::byte> data;
  // The size can grow between the two calls only through another thread, which the lock stops.
  size_t size = 0;
  vk_check(vkGetPipelineCacheData(context_.device(), cache_, &size, nullptr), "vkGetPipelineCacheData");
  data.resize(size);
  vk_check(vkGetPipelineCacheData(context_.device(), cache_, &size, data.data()), "vkGetPipelineCacheData");
  data.resize(size);
  return data;
}

bool PipelineCache::merge(std::span<const std::byte> driver_data) {
  auto info = vk_struct<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
  info.initialDataSize = driver_data.size();
  info.pInitialData = driver_data.data();
  VkPipelineCache loaded = VK_NULL_HANDLE;
  if (vkCreatePipelineCache(context_.device(), &info, nullptr, &loaded) != VK_SUCCESS) return false;
  std::lock_guard lock(mutex_);
  const VkResult merged = vkMergePipelineCaches(context_.device(), cache_, 1, &loaded);
  vkDestroyPipelineCache(context_.device(), loaded, nullptr);
  return merged == VK_SUCCESS;
}

// The pipeline under `key`, or a new one from create(pipeline, feedback), counted.
template <typename Create>
const Pipeline& PipelineCache::find_or_make(std::string key, Create&& create) {
  std::lock_guard lock(mutex_);
  if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
  CreationFeedback feedback;
  Pipeline p = create(feedback);
  ++created_;
  if (feedback.cache_hit()) ++driver_cache_hits_;
  return pipelines_.emplace(std::move(key), p).first->second;
}

const Pipeline& PipelineCache::compute(const ComputePipelineDesc& desc) {
  check_spirv(desc.shader, desc.name, "compute");
  Key key;
  key.add('C').add_all(desc.shader);
  add_layout(key, desc.bindings, desc.push_constant_bytes);
  key.add_all(std::span(desc.constants));
  return find_or_make(key.take(), [&](CreationFeedback& feedback) {
    Pipeline p = make_layout(context_, desc.bindings, desc.push_constant_bytes, VK_SHADER_STAGE_COMPUTE_BIT,
                             VK_PIPELINE_BIND_POINT_COMPUTE);
    return finish(context_, p, desc.name, [&](Pipeline& out) {
      ShaderModule module(context_, desc.shader);
      auto info =
          vk_struct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO, feedback.chain(1));
      info.stage = vk_struct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
      info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
      info.stage.module = module.handle();
      info.stage.pName = "main";
      const std::vector<VkSpecializationMapEntry> entries = constant_entries(desc.constants);
      const VkSpecializationInfo constants = specialization_info(entries, desc.constants);
      if (!entries.empty()) info.stage.pSpecializationInfo = &constants;
      info.layout = out.layout;
      vk_check(vkCreateComputePipelines(context_.device(), cache_, 1, &info, nullptr, &out.handle),
               "vkCreateComputePipelines", "for '" + desc.name + "'");
    });
  });
}

const Pipeline& PipelineCache::graphics(const GraphicsPipelineDesc& desc) {
  check_spirv(desc.vertex_shader, desc.name, "vertex");
  check_spirv(desc.fragment_shader, desc.name, "fragment");
  Key key;
  key.add('G').add_all(desc.vertex_shader).add_all(desc.fragment_shader);
  add_layout(key, desc.bindings, desc.push_constant_bytes);
  key.add_all(std::span(desc.vertex_bindings)).add_all(std::span(desc.vertex_attributes));
  key.add(desc.topology).add(desc.cull).add(desc.front_face).add_all(std::span(desc.color_formats)).add(desc.blend);
  key.add(desc.depth_format).add(desc.depth_test).add(desc.depth_write).add(desc.depth_compare);
  key.add_all(std::span(desc.fragment_constants));
  return find_or_make(key.take(), [&](CreationFeedback& feedback) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    Pipeline p =
        make_layout(context_, desc.bindings, desc.push_constant_bytes, stages, VK_PIPELINE_BIND_POINT_GRAPHICS);
    return finish(context_, p, desc.name, [&](Pipeline& out) {
      ShaderModule vertex(context_, desc.vertex_shader), fragment(context_, desc.fragment_shader);
      VkPipelineShaderStageCreateInfo shader_stages[2];
      for (auto& s : shader_stages)
        s = vk_struct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
      shader_stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
      shader_stages[0].module = vertex.handle();
      shader_stages[0].pName = "main";
      shader_stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
      shader_stages[1].module = fragment.handle();
      shader_stages[1].pName = "main";
      const std::vector<VkSpecializationMapEntry> entries = constant_entries(desc.fragment_constants);
      const VkSpecializationInfo constants = specialization_info(entries, desc.fragment_constants);
      if (!entries.empty()) shader_stages[1].pSpecializationInfo = &constants;

      auto vertex_input =
          vk_struct<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
      vertex_input.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertex_bindings.size());
      vertex_input.pVertexBindingDescriptions = desc.vertex_bindings.data();
      vertex_input.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.vertex_attributes.size());
      vertex_input.pVertexAttributeDescriptions = desc.vertex_attributes.data();
      auto assembly = vk_struct<VkPipelineInputAssemblyStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
      assembly.topology = desc.topology;
      auto viewport =
          vk_struct<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
      viewport.viewportCount = viewport.scissorCount = 1;  // both dynamic
      auto raster =
          vk_struct<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
      raster.polygonMode = VK_POLYGON_MODE_FILL;
      raster.cullMode = desc.cull;
      raster.frontFace = desc.front_face;
      raster.lineWidth = 1;
      auto multisample =
          vk_struct<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
      multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
      auto depth =
          vk_struct<VkPipelineDepthStencilStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
      depth.depthTestEnable = desc.depth_test;
      depth.depthWriteEnable = desc.depth_write;
      depth.depthCompareOp = desc.depth_compare;

      VkPipelineColorBlendAttachmentState blend{};
      blend.colorWriteMask =
          VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
      if (desc.blend != Blend::none) {
        blend.blendEnable = VK_TRUE;
        const bool over = desc.blend != Blend::additive;
        blend.srcColorBlendFactor = desc.blend == Blend::alpha ? VK_BLEND_FACTOR_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        blend.dstColorBlendFactor = over ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        blend.dstAlphaBlendFactor = over ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_ADD;
      }
      std::vector<VkPipelineColorBlendAttachmentState> blends(desc.color_formats.size(), blend);
      auto color =
          vk_struct<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
      color.attachmentCount = static_cast<uint32_t>(blends.size());
      color.pAttachments = blends.data();
      const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
      auto dynamic = vk_struct<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
      dynamic.dynamicStateCount = 2;
      dynamic.pDynamicStates = dynamic_states;

      auto rendering =
          vk_struct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO, feedback.chain(2));
      rendering.colorAttachmentCount = static_cast<uint32_t>(desc.color_formats.size());
      rendering.pColorAttachmentFormats = desc.color_formats.data();
      rendering.depthAttachmentFormat = desc.depth_format;

      auto info = vk_struct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering);
      info.stageCount = 2;
      info.pStages = shader_stages;
      info.pVertexInputState = &vertex_input;
      info.pInputAssemblyState = &assembly;
      info.pViewportState = &viewport;
      info.pRasterizationState = &raster;
      info.pMultisampleState = &multisample;
      info.pDepthStencilState = &depth;
      info.pColorBlendState = &color;
      info.pDynamicState = &dynamic;
      info.layout = out.layout;
      vk_check(vkCreateGraphicsPipelines(context_.device(), cache_, 1, &info, nullptr, &out.handle),
               "vkCreateGraphicsPipelines", "for '" + desc.name + "'");
    });
  });
}

}  // namespace lg
