// Depth from a light through lighting.deferred's shadow shaders (shaders/shadow_draw.glsl): the
// push constants and the block of one draw and the pipeline, shared by lighting.deferred's shadow maps and
// gi.voxel's.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/mat4x4.hpp>

#include "runtime/gpu/descriptors.h"

namespace lg {

class PassContext;
struct Pipeline;

struct ShadowDrawPush {  // shaders/shadow_draw.glsl
  glm::mat4 shadow_from_world;
};

// Depth of `depth_format` from positions (shaders/shadow.vert), or alpha-tested against the
// draw's base colour (shaders/shadow_masked.*), binding the draw's block at 0 (draw_block(0, ...),
// draw_constants.h; and the base
// colour at 1 when alpha-tested). Both sides of every face: a wall modelled as one single-sided plane must not
// let light through from behind.
const Pipeline& shadow_depth_pipeline(PassContext& ctx, VkFormat depth_format, bool alpha_tested);

}  // namespace lg
