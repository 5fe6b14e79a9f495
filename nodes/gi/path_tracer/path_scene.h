// Everything the path tracer traces against, built once from a SceneView and shared by all
// threads: the flattened geometry in Embree with its shading attributes, the materials and
// textures, the lights, and the environment (none, env.sky's sky and sun, or an env.load map).
#pragma once

#include <optional>
#include <vector>

#include "nodes/gi/path_tracer/environment_map.h"
#include "nodes/gi/path_tracer/path_lights.h"
#include "nodes/raytrace/ray_scene.h"
#include "nodes/raytrace/surface_lookup.h"
#include "runtime/scene/scene_view.h"

namespace lg {

// What a graph's environment node gives the path tracer.
struct PathEnvironment {
  std::optional<EnvironmentMap> map;
  std::vector<PathLights::DistantDisk> disks;  // the sky's sun

  static PathEnvironment none() { return {}; }
  static PathEnvironment sky(const SkyParams& params);
  static PathEnvironment image(Equirect image);  // intensity applied, texels finite
};

class PathScene {
 public:
  // Throws std::invalid_argument for a bad mesh or a non-finite position, naming the mesh.
  PathScene(SceneView view, PathEnvironment environment);

  const SceneView& view() const { return view_; }
  const RayScene& rays() const { return rays_; }
  const SurfaceLookup& surfaces() const { return surfaces_; }
  const PathLights& lights() const { return lights_; }
  const EnvironmentMap* environment() const { return environment_ ? &*environment_ : nullptr; }

 private:
  SceneView view_;
  SurfaceLookup surfaces_;
  RayScene rays_;
  PathLights lights_;
  std::optional<EnvironmentMap> environment_;
};

}  // namespace lg
