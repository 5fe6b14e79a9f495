// Per-draw constants of passes that rasterize the scene's meshes as the G-buffer pass does
// (nodes/scene/gbuffer/shaders/draw.glsl, std430): world and last frame's world matrices, the
// normal matrix, and the draw's material.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

struct DrawConstants {
  glm::mat4 world, previous_world, normal_matrix;
  glm::vec4 base_color, material;
};

// One per SceneView::draws entry, in order.
std::vector<DrawConstants> draw_constants(const SceneView& scene);

}  // namespace lg
