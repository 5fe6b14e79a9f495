#include "runtime/scene/load_world.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>

#include "runtime/scene/mesh_import.h"
#include "runtime/scene/mesh_tools.h"
#include "runtime/scene/scene_error.h"
#include "runtime/scene/scene_file.h"

namespace lg {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void add_framing_camera(World& world) {
  Bounds bounds;
  world.each<MeshRenderer>([&](Entity e, const MeshRenderer& r) {
    if (r.mesh < 0 || static_cast<size_t>(r.mesh) >= world.meshes().size()) return;
    Bounds b = transformed_bounds(*world.meshes()[static_cast<size_t>(r.mesh)], world.world_matrix(e));
    if (!b.empty()) {
      bounds.add(b.min);
      bounds.add(b.max);
    }
  });
  glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  float radius = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
  Camera camera;
  // The bounding sphere fits the vertical field of view with a 10% margin.
  float distance = 1.1f * radius / std::sin(camera.vertical_fov * 0.5f);
  camera.near_plane = std::max(1e-3f, 0.01f * distance);
  camera.focus_distance = distance;
  glm::vec3 position = center + distance * glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  Entity e = world.create("camera");
  world.add<Transform>(e, {position, look_rotation(center - position), glm::vec3(1.0f), {}});
  world.add<Camera>(e, camera);
}

}  // namespace

void add_viewing_defaults(World& world) {
  if (world.count<Camera>() == 0) add_framing_camera(world);
  bool lit = world.count<DirectionalLight>() + world.count<PointLight>() + world.count<SpotLight>() +
                 world.count<SphereLight>() + world.count<TubeLight>() + world.count<RectLight>() >
             0;
  if (!lit) {
    Entity sun = world.create("sun");
    world.add<Transform>(sun, {glm::vec3(0.0f), look_rotation({-0.4f, -0.8f, -0.45f}), glm::vec3(1.0f), {}});
    world.add<DirectionalLight>(sun, {{1.0f, 0.95f, 0.85f}, 8.0f, 0.00465f, true});
  }
  if (world.count<EnvironmentLight>() == 0) world.add<EnvironmentLight>(world.create("sky"), {"", 1.0f});
}

World load_world(const std::string& path, const WorldLoadOptions& options) {
  std::string ext = lower_extension(path);
  if (ext == ".json") return load_scene_file(path, options.asset_roots, options.read_occlusion);
  if (ext != ".gltf" && ext != ".glb" && ext != ".obj")
    throw SceneError(path, "unknown kind of world file '" + ext + "'; expected .json, .gltf, .glb or .obj");
  World world;
  world.name = std::filesystem::path(path).stem().string();
  if (ext == ".obj")
    import_obj(world, path);
  else
    import_gltf(world, path);
  add_viewing_defaults(world);
  return world;
}

}  // namespace lg
