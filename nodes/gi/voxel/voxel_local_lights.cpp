#include "nodes/gi/voxel/voxel_local_lights.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "nodes/lighting/deferred/light_buffers.h"

namespace lg {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

VoxelLocalLight light(glm::vec3 position, float range, glm::vec3 intensity, float size, glm::vec3 axis,
                      VoxelLightKind kind) {
  VoxelLocalLight l;
  l.position_range = glm::vec4(position, std::max(range, 0.0f));
  l.intensity_size = glm::vec4(glm::max(intensity, glm::vec3(0.0f)), size);
  l.axis_kind = glm::vec4(axis, float(int(kind)));
  return l;
}

}  // namespace

VoxelLocalLights voxel_local_lights(const SceneView& scene) {
  VoxelLocalLights out;
  auto add = [&out](const VoxelLocalLight& l) {
    if (out.count < kMaxVoxelLocalLights) out.lights[out.count++] = l;
  };
  const glm::vec3 none(0.0f);
  for (const PointLightData& p : scene.point_lights)
    add(light(p.position, p.range, p.intensity, 0.0f, none, VoxelLightKind::every_way));
  for (const SpotLightData& s : scene.spot_lights) {
    VoxelLocalLight l = light(s.position, s.range, s.intensity, 0.0f, glm::normalize(s.direction), VoxelLightKind::spot);
    l.spot = glm::vec4(spot_ramp(s), 0.0f, 0.0f);  // lighting.deferred's ramp
    add(l);
  }
  // A uniform Lambertian sphere of radiance L sends L pi r^2 every way; outside it the irradiance
  // is exactly I cos / d^2, so its size is r^2 only to keep it finite inside.
  for (const SphereLightData& s : scene.sphere_lights)
    add(light(s.center, 0.0f, s.radiance * (kPi * s.radius * s.radius), s.radius * s.radius, none,
              VoxelLightKind::every_way));
  // A capsule's mean projected area is a quarter of its surface (Cauchy): pi r^2 + pi r length / 2.
  for (const TubeLightData& t : scene.tube_lights) {
    const float length = glm::length(t.end1 - t.end0);
    const float area = kPi * t.radius * t.radius + 0.5f * kPi * t.radius * length;
    add(light(0.5f * (t.end0 + t.end1), 0.0f, t.radiance * area, area / kPi, none, VoxelLightKind::every_way));
  }
  // A rectangle of area A and radiance L sends L A cos toward the side it faces (both with
  // two_sided); its size A / pi makes a disk's on-axis irradiance exact.
  for (const RectLightData& r : scene.rect_lights) {
    const glm::vec3 normal = glm::cross(r.half_x, r.half_y);
    const float area = 4.0f * glm::length(normal);
    if (!(area > 0.0f)) continue;
    add(light(r.center, 0.0f, r.radiance * area, area / kPi, normal / (0.25f * area),
              r.two_sided ? VoxelLightKind::two_sided : VoxelLightKind::one_sided));
  }
  return out;
}

}  // namespace lg
