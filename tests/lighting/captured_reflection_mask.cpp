#include "tests/lighting/captured_reflection_mask.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/raytrace/camera_hit.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/ray_offset.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::test {

std::vector<uint8_t> captured_reflection_mask(const World& world, uint32_t width, uint32_t height, float alpha) {
  const SceneView view = make_scene_view(world, float(width) / float(height));
  const WorldMesh mesh = make_world_mesh(view);
  const RayScene rays(mesh, view);
  // Per triangle, whether its draw is captured (parts are the draws in order).
  std::vector<uint8_t> captured(rays.triangle_count(), 1);
  for (size_t d = 0; d < mesh.parts.size() && d < view.draws.size(); ++d)
    if (!view.draws[d].captured_by_probes)
      std::fill_n(captured.begin() + mesh.parts[d].first_triangle, mesh.parts[d].triangle_count, 0);
  const CameraPixels pixels(view.camera, width, height);
  const float tilt = 4.0f * alpha;
  std::vector<uint8_t> mask(size_t(width) * height, 0);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const glm::dvec3 direction = pixels.ray_direction(x, y);
      const auto hit = first_camera_hit(rays, pixels.eye(), direction, true);
      if (!hit) continue;
      const glm::vec3 n = hit->front_face ? hit->hit.normal : -hit->hit.normal;
      const glm::vec3 r = glm::reflect(glm::vec3(direction), n);
      const glm::vec3 t = glm::normalize(glm::cross(std::abs(r.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), r));
      const glm::vec3 b = glm::cross(r, t);
      const glm::vec3 origin = offset_ray_origin(glm::vec3(hit->position), n);
      bool sees_only_captured = true;
      for (int i = 0; i < 9 && sees_only_captured; ++i) {
        const float angle = float(i) * 0.7853982f;  // 8 directions around the mirror one (i = 0)
        const glm::vec3 d =
            i == 0 ? r : glm::normalize(r + std::tan(tilt) * (std::cos(angle) * t + std::sin(angle) * b));
        if (glm::dot(d, n) <= 0.0f) continue;  // below the surface: no light from there
        const auto seen = rays.intersect(origin, d, 1e30f);
        sees_only_captured = !seen || captured[seen->primitive];
      }
      mask[size_t(y) * width + x] = sees_only_captured ? 1 : 0;
    }
  return mask;
}

}  // namespace lg::test
