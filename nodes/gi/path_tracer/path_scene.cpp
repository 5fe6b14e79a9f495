#include "nodes/gi/path_tracer/path_scene.h"

#include "nodes/raytrace/world_mesh.h"

namespace lg {

PathEnvironment PathEnvironment::sky(const SkyParams& params) {
  const SkyModel model = make_sky_model(params);
  PathEnvironment out;
  out.map = EnvironmentMap::from_sky(model);
  // env.sky draws no sun below the horizon.
  if (model.sun.y > 0.0) out.disks.push_back({model.sun, kSunAngularRadius, glm::dvec3(model.sun_radiance)});
  return out;
}

PathEnvironment PathEnvironment::image(Equirect image) {
  PathEnvironment out;
  out.map = EnvironmentMap::from_image(std::move(image));
  return out;
}

PathScene::PathScene(SceneView view, PathEnvironment environment)
    : view_(std::move(view)),
      surfaces_(make_world_mesh(view_)),
      rays_(surfaces_.mesh(), view_),
      lights_(view_, std::move(environment.disks)),
      environment_(std::move(environment.map)) {}

}  // namespace lg
