// blend_draws_back_to_front(): sorting the transparent draws by view depth.
#include "nodes/scene/forward_transparent/blend_order.h"

#include <algorithm>
#include <glm/vec4.hpp>

#include "runtime/scene/mesh_tools.h"

namespace lg {

std::vector<glm::vec3> mesh_centers(const SceneView& scene) {
  std::vector<glm::vec3> out(scene.meshes.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    if (!scene.meshes[i]) continue;
    const Bounds b = transformed_bounds(*scene.meshes[i], glm::mat4(1.0f));
    if (!b.empty()) out[i] = b.center();
  }
  return out;
}

std::vector<uint32_t> blend_draws_back_to_front(const SceneView& scene, const std::vector<glm::vec3>& centers) {
  struct Keyed {
    float depth;
    uint32_t draw;
  };
  std::vector<Keyed> keyed;
  for (uint32_t i = 0; i < scene.draws.size(); ++i) {
    const DrawItem& d = scene.draws[i];
    if (scene.material_of(d).alpha_mode != AlphaMode::blend) continue;
    const glm::vec3 center = d.mesh >= 0 && size_t(d.mesh) < centers.size() ? centers[size_t(d.mesh)] : glm::vec3(0.0f);
    // The camera looks along its view space's -Z: depth is -z.
    keyed.push_back({-(scene.camera.view * (d.world * glm::vec4(center, 1.0f))).z, i});
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) { return a.depth > b.depth; });
  std::vector<uint32_t> out;
  for (const Keyed& k : keyed) out.push_back(k.draw);
  return out;
}

}  // namespace lg
