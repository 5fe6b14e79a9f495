// What the passes shading with nodes/scene/forward_transparent/shaders/forward_shading.glsl bind,
// and their pipeline: scene.forward_transparent's blended draws and gi.reflection_capture's
// raster capture of cube faces, which light meshes the same way.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/vec4.hpp>
#include <span>
#include <string>
#include <vector>

#include "nodes/lighting/deferred/light_buffers.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/pipeline.h"

namespace lg {

// forward_shading.glsl's Settings (std140, binding 20).
struct ForwardSettings {
  uint32_t flags;  // 1: image-based light, 2: its diffuse from SH, 4: distance to the camera in alpha
  float intensity;
  float volume_normal_bias = 0.0f, volume_view_bias = 0.0f;  // the captures' probe volume (raster_capture.h)
  glm::vec4 clip_plane{0.0f, 0.0f, 0.0f, 1.0f};              // (0, 0, 0, 1): nothing clipped
  uint32_t volume_count = 0;
  uint32_t unused[3] = {};
};

// The environment's inputs (bindings 6 to 9) and any 2D image to sample, bound where the shaders
// read nothing (the shadow map and the local shadow atlas, which the constants say were not
// drawn) or where an input is unused (the settings' flags skip it).
struct ForwardResources {
  VkBuffer sh;
  VkImageView irradiance, specular, brdf_lut, placeholder_2d;
  VkSampler linear, nearest;
};

// Every write but the material's textures (material_textures.h): the light constants at 0
// (the caller may replace it), draws at 1, the environment, the light lists, the settings at 20
// and the placeholder at 10, 14 and 19 (forward.frag's scene depth: the caller's to replace).
std::vector<DescriptorWrite> forward_writes(const LightBuffers& lights, VkBuffer draws, VkBuffer settings,
                                            const ForwardResources& resources);

// The G-buffer's textured vertex stage (gbuffer.vert) with `fragment`, every binding of
// forward_writes() and the material's, the draw index as push constant; back faces culled
// unless `double_sided`.
GraphicsPipelineDesc forward_pipeline_desc(std::string name, std::span<const uint32_t> fragment, VkFormat color,
                                           bool double_sided);

}  // namespace lg
