#include "nodes/lighting/deferred/light_culling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lg {
namespace {

// Range 0 (or anything not positive, or NaN) is no cut-off.
float influence_radius(float range) {
  return range > 0.0f ? range : INFINITY;
}

template <class Light>
std::vector<Light> reaching(const Frustum& frustum, const std::vector<Light>& lights, bool cull) {
  std::vector<Light> out;
  for (const Light& l : lights)
    if (!cull || reaches(frustum, l)) out.push_back(l);
  return out;
}

}  // namespace

bool reaches(const Frustum& frustum, const PointLightData& light) {
  return touches(frustum, light.position, influence_radius(light.range));
}

// The cone cut by the range sphere: its points are position + t v for t in [0, range] and unit
// v within the outer angle of the axis (the falloff is exactly 0 at the outer angle). Along a
// plane's normal n the cone reaches n.v at most 1 where n lies inside the cone, else
// cos(angle(n, axis) - outer); so the farthest point is the apex where that is not positive and
// range times it beyond the apex otherwise (never outside the plane without a range).
bool reaches(const Frustum& frustum, const SpotLightData& light) {
  const float cos_outer = std::cos(light.outer_cone_angle), sin_outer = std::sin(light.outer_cone_angle);
  for (const glm::vec4& p : frustum.planes) {
    const glm::vec3 n(p);
    const float apex = glm::dot(n, light.position) + p.w;
    const float c = glm::dot(n, light.direction);  // |n| is 1 (0 for a plane that bounds nothing)
    const float farthest = c >= cos_outer ? 1.0f : c * cos_outer + std::sqrt(std::max(0.0f, 1.0f - c * c)) * sin_outer;
    if (farthest <= 0.0f) {
      if (apex < 0.0f) return false;
    } else if (light.range > 0.0f && apex + light.range * farthest < 0.0f) {
      return false;
    }
  }
  return true;
}

SceneView lights_in_view(const SceneView& scene, bool cull) {
  const Frustum frustum = view_frustum(scene.camera);
  SceneView out;
  out.camera = scene.camera;
  out.directional_lights = scene.directional_lights;
  out.point_lights = reaching(frustum, scene.point_lights, cull);
  out.spot_lights = reaching(frustum, scene.spot_lights, cull);
  out.sphere_lights = scene.sphere_lights;
  out.tube_lights = scene.tube_lights;
  out.rect_lights = scene.rect_lights;
  return out;
}

}  // namespace lg
