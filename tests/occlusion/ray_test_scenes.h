// Small analytic scenes for the ray-tracing tests, built from the procedural meshes
// (runtime/scene/mesh_generators.h) placed by transforms.
#pragma once

#include <glm/mat4x4.hpp>
#include <utility>
#include <vector>

#include "nodes/raytrace/ray_scene.h"
#include "runtime/scene/scene_view.h"

namespace lg::test {

// A SceneView drawing each mesh once with its world transform.
SceneView scene_of(std::vector<std::pair<MeshData, glm::mat4>> placed);

// The floor y = 0 as a square of side `size` centred on the origin, facing +Y.
std::pair<MeshData, glm::mat4> floor_quad(float size);
// A wall in the plane x = -distance from y = 0 to y = height, `width` long along Z centred on
// z = 0, facing +X (toward the origin).
std::pair<MeshData, glm::mat4> wall_quad(float distance, float height, float width);

}  // namespace lg::test
