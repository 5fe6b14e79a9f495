// draw_constants(): the scene's draws as draw.glsl reads them.
#include "nodes/scene/gbuffer/draw_constants.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace lg {

std::vector<DrawConstants> draw_constants(const SceneView& scene) {
  std::vector<DrawConstants> out;
  out.reserve(scene.draws.size());
  for (const DrawItem& d : scene.draws) {
    const PbrMaterial& m = scene.material_of(d);
    out.push_back({d.world, d.previous_world, glm::mat4(glm::transpose(glm::inverse(glm::mat3(d.world)))), m.base_color,
                   glm::vec4(m.roughness, m.metalness, 0.0f, 0.0f)});
  }
  return out;
}

}  // namespace lg
