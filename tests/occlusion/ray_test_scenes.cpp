// Analytic scenes for the ray-tracing tests (ray_test_scenes.h).
#include "tests/occlusion/ray_test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "runtime/scene/mesh_generators.h"

namespace lg::test {

SceneView scene_of(std::vector<std::pair<MeshData, glm::mat4>> placed) {
  SceneView view;
  for (auto& [mesh, world] : placed) {
    DrawItem draw;
    draw.mesh = int(view.meshes.size());
    draw.world = world;
    view.meshes.push_back(std::make_shared<const MeshData>(std::move(mesh)));
    view.draws.push_back(draw);
  }
  return view;
}

std::pair<MeshData, glm::mat4> floor_quad(float size) {
  return {make_quad(size, size), glm::mat4(1.0f)};
}

std::pair<MeshData, glm::mat4> wall_quad(float distance, float height, float width) {
  // The quad faces +Y; a quarter turn about Z takes +Y to +X, its X extent to Y.
  glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(-distance, height * 0.5f, 0.0f));
  world = glm::rotate(world, -float(std::numbers::pi) / 2.0f, glm::vec3(0.0f, 0.0f, 1.0f));
  return {make_quad(height, width), world};
}

}  // namespace lg::test
