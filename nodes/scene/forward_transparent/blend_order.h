// The order scene.forward_transparent draws transparent surfaces in: the draws whose material
// is alphaMode BLEND, farthest first by the view depth of the centre of their mesh's bounds,
// so that "over" blending composites them back to front whatever order the scene lists them in.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

// The centre of each mesh's bounds in its own space, per SceneView::meshes entry (the origin
// for an empty or null mesh); changes only with SceneView::version.
std::vector<glm::vec3> mesh_centers(const SceneView& scene);

// Indices into scene.draws of the BLEND draws, farthest from the camera first (ties keep the
// scene's order).
std::vector<uint32_t> blend_draws_back_to_front(const SceneView& scene, const std::vector<glm::vec3>& centers);

}  // namespace lg
