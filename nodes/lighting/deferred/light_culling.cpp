#include "nodes/lighting/deferred/light_culling.h"

#include <cmath>

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

// The range sphere, not the cone: a cone's bounds would be tighter, but the sphere is enough to
// drop lights far from the view, which is where most of them are.
bool reaches(const Frustum& frustum, const SpotLightData& light) {
  return touches(frustum, light.position, influence_radius(light.range));
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
