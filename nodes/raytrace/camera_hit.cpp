#include "nodes/raytrace/camera_hit.h"

#include <glm/geometric.hpp>
#include <limits>

#include "nodes/raytrace/ray_offset.h"

namespace lg {
namespace {

// Back faces the ray passes through when culling; more would mean the pixel looks through a
// stack of inside-out geometry, which no real scene has.
constexpr int kMaxCulledFaces = 16;

}  // namespace

std::optional<CameraHit> first_camera_hit(const RayScene& scene, glm::dvec3 eye, glm::dvec3 direction,
                                          bool cull_backfaces) {
  glm::vec3 origin(eye);
  const glm::vec3 dir(direction);
  for (int k = 0; k <= kMaxCulledFaces; ++k) {
    const std::optional<RayHit> hit = scene.intersect(origin, dir, std::numeric_limits<float>::infinity());
    if (!hit) return std::nullopt;
    const glm::dvec3 position = glm::dvec3(origin) + glm::dvec3(dir) * double(hit->distance);
    const bool front = glm::dot(glm::dvec3(hit->normal), direction) < 0.0;
    if (front || !cull_backfaces || !scene.single_sided(hit->primitive)) return CameraHit{*hit, position, front};
    origin = offset_ray_origin(glm::vec3(position), dir);  // continue behind the culled face
  }
  return std::nullopt;
}

}  // namespace lg
