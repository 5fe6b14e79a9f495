// Where the directional light's shadow map looks: an orthographic projection along the light
// that holds the bounds of every draw, into Vulkan clip space with reversed depth (1 nearest
// the light).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/scene_view.h"

namespace lg {

// World-space bounds of every draw's vertices; a scene without draws gets a unit box.
Bounds scene_bounds(const SceneView& scene);

// `direction`: unit, the way the light travels.
glm::mat4 shadow_from_world(const Bounds& bounds, glm::vec3 direction);

}  // namespace lg
