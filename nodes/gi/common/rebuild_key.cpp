#include "nodes/gi/common/rebuild_key.h"

#include "runtime/scene/scene_view.h"

namespace lg {

void append_key(std::vector<std::byte>& key, const void* data, size_t bytes) {
  const auto* first = static_cast<const std::byte*>(data);
  key.insert(key.end(), first, first + bytes);
}

void append_geometry_key(std::vector<std::byte>& key, const SceneView& scene, std::span<const DrawConstants> draws) {
  append_key(key, &scene.version, sizeof(scene.version));
  append_key(key, draws.data(), draws.size_bytes());
  for (const DrawItem& d : scene.draws) append_key(key, &d.mesh, sizeof(d.mesh));
}

bool is_static_result(const Plan& plan, const PlanAccess& access) {
  const int first = plan.resources[access.resource].first;
  return first >= 0 && plan.passes[first].is_static;
}

}  // namespace lg
