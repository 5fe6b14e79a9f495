#include "nodes/gi/common/main_light.h"

#include "nodes/lighting/deferred/light_buffers.h"
#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {

int main_directional_light(const SceneView& scene) {
  const int caster = shadow_caster(scene);
  return caster >= 0 || scene.directional_lights.empty() ? caster : 0;
}

Bounds draws_bounds(const SceneView& scene, std::span<const Bounds> mesh_boxes) {
  Bounds b;
  for (const DrawItem& d : scene.draws) {
    if (d.mesh < 0 || size_t(d.mesh) >= mesh_boxes.size()) continue;
    const Bounds box = transform_bounds(mesh_boxes[d.mesh], d.world);
    if (!box.empty()) b.add(box.min), b.add(box.max);
  }
  return b.empty() ? Bounds{glm::vec3(-0.5f), glm::vec3(0.5f)} : b;
}

}  // namespace lg
