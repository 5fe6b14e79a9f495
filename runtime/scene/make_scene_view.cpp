#include "runtime/scene/make_scene_view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <stdexcept>
#include <unordered_map>

#include "runtime/scene/mesh_plane.h"
#include "runtime/scene/projection.h"

namespace lg {
namespace {

glm::vec3 point(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}
glm::vec3 vector(const glm::mat4& m, glm::vec3 v) {
  return glm::vec3(m * glm::vec4(v, 0.0f));
}

// Radii scale with the largest axis scale (lights stay spheres and capsules).
float max_scale(const glm::mat4& m) {
  return std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

glm::mat4 without_scale(const glm::mat4& m) {
  glm::mat4 r = m;
  for (int axis = 0; axis < 3; ++axis) {
    float length = glm::length(glm::vec3(m[axis]));
    if (length > 0.0f) r[axis] /= length;
  }
  return r;
}

// The holder of T with the lowest index: a choice that survives removals of other entities.
template <class T>
Entity first_with(const World& world) {
  Entity chosen;
  world.each<T>([&](Entity e, const T&) {
    if (chosen.is_null() || e.index < chosen.index) chosen = e;
  });
  return chosen;
}

void add_camera(const World& world, float aspect_ratio, SceneView& view) {
  Entity chosen = world.has<Camera>(world.active_camera) ? world.active_camera : first_with<Camera>(world);
  Camera camera = chosen.is_null() ? Camera{} : world.get<Camera>(chosen);
  glm::mat4 frame = chosen.is_null() ? glm::mat4(1.0f) : without_scale(world.world_matrix(chosen));
  CameraView& c = view.camera;
  c.view = glm::affineInverse(frame);
  c.projection = reversed_z_infinite_perspective(camera.vertical_fov, aspect_ratio, camera.near_plane);
  c.previous_view_projection = c.projection * c.view;
  c.position = glm::vec3(frame[3]);
  c.vertical_fov = camera.vertical_fov;
  c.near_plane = camera.near_plane;
  c.aperture = camera.aperture;
  c.focus_distance = camera.focus_distance;
}

void add_lights(const World& world, SceneView& view) {
  world.each<DirectionalLight>([&](Entity e, const DirectionalLight& l) {
    glm::vec3 d = vector(world.world_matrix(e), {0.0f, 0.0f, -1.0f});
    float length = glm::length(d);
    view.directional_lights.push_back({length > 0.0f ? d / length : glm::vec3(0.0f, -1.0f, 0.0f), l.color * l.intensity,
                                       l.angular_radius, l.casts_shadows});
  });
  world.each<PointLight>([&](Entity e, const PointLight& l) {
    view.point_lights.push_back(
        {point(world.world_matrix(e), glm::vec3(0.0f)), l.color * l.intensity, l.range, l.casts_shadows});
  });
  world.each<SpotLight>([&](Entity e, const SpotLight& l) {
    glm::mat4 m = world.world_matrix(e);
    glm::vec3 d = vector(m, {0.0f, 0.0f, -1.0f});
    float length = glm::length(d);
    view.spot_lights.push_back({point(m, glm::vec3(0.0f)), length > 0.0f ? d / length : glm::vec3(0.0f, -1.0f, 0.0f),
                                l.color * l.intensity, l.range, l.inner_cone_angle, l.outer_cone_angle,
                                l.casts_shadows});
  });
  world.each<SphereLight>([&](Entity e, const SphereLight& l) {
    glm::mat4 m = world.world_matrix(e);
    view.sphere_lights.push_back(
        {point(m, glm::vec3(0.0f)), l.radius * max_scale(m), l.color * l.intensity, l.casts_shadows});
  });
  world.each<TubeLight>([&](Entity e, const TubeLight& l) {
    glm::mat4 m = world.world_matrix(e);
    glm::vec3 half{l.length * 0.5f, 0.0f, 0.0f};
    view.tube_lights.push_back(
        {point(m, -half), point(m, half), l.radius * max_scale(m), l.color * l.intensity, l.casts_shadows});
  });
  world.each<RectLight>([&](Entity e, const RectLight& l) {
    glm::mat4 m = world.world_matrix(e);
    view.rect_lights.push_back({point(m, glm::vec3(0.0f)), vector(m, {l.width * 0.5f, 0.0f, 0.0f}),
                                // -Y so that cross(half_x, half_y), the side that emits, is local -Z.
                                vector(m, {0.0f, -l.height * 0.5f, 0.0f}), l.color * l.intensity, l.two_sided,
                                l.casts_shadows});
  });
}

void add_draws(const World& world, const SceneView* previous, SceneView& view) {
  std::unordered_map<uint64_t, glm::mat4> previous_worlds;
  if (previous)
    for (const auto& d : previous->draws) previous_worlds.emplace(d.entity, d.world);
  world.each<MeshRenderer>([&](Entity e, const MeshRenderer& r) {
    DrawItem d;
    d.mesh = r.mesh;
    d.material = r.material;
    d.world = world.world_matrix(e);
    auto found = previous_worlds.find(e.id());
    d.previous_world = found != previous_worlds.end() ? found->second : d.world;
    d.entity = e.id();
    d.captured_by_probes = r.captured_by_probes;
    view.draws.push_back(d);
  });
  // Dense order changes with removals; entity order keeps the view stable from frame to frame.
  std::sort(view.draws.begin(), view.draws.end(), [](const DrawItem& a, const DrawItem& b) {
    return static_cast<uint32_t>(a.entity) < static_cast<uint32_t>(b.entity);
  });
}

// Draws of one floor split into pieces share their plane: it is mirrored once.
void add_reflector_planes(const World& world, SceneView& view) {
  world.each<MeshRenderer>([&](Entity e, const MeshRenderer& r) {
    if (!r.reflector_plane) return;
    const glm::vec4 plane = transform_plane(*r.reflector_plane, world.world_matrix(e));
    const auto same = [&](const glm::vec4& q) {
      return glm::dot(glm::vec3(plane), glm::vec3(q)) > 0.99999f && std::abs(plane.w - q.w) < 1e-4f;
    };
    if (std::none_of(view.planar_reflectors.begin(), view.planar_reflectors.end(), same))
      view.planar_reflectors.push_back(plane);
  });
}

}  // namespace

SceneView make_scene_view(const World& world, float aspect_ratio, const SceneView* previous) {
  if (!(aspect_ratio > 0.0f) || !std::isfinite(aspect_ratio))
    throw std::invalid_argument("make_scene_view: the aspect ratio must be a positive number");
  SceneView view;
  view.name = world.name;
  view.version = world.asset_revision();
  add_camera(world, aspect_ratio, view);
  if (previous) view.camera.previous_view_projection = previous->camera.projection * previous->camera.view;
  view.meshes = world.meshes();  // shared pointers: the assets themselves are not copied
  view.textures = world.textures();
  view.materials = world.materials();
  add_draws(world, previous, view);
  add_reflector_planes(world, view);
  add_lights(world, view);
  if (Entity env = first_with<EnvironmentLight>(world); !env.is_null()) {
    view.has_environment = true;
    view.environment = {world.get<EnvironmentLight>(env).path, world.get<EnvironmentLight>(env).intensity};
  }
  world.each<IrradianceVolume>([&](Entity e, const IrradianceVolume& v) {
    view.irradiance_volumes.push_back({world.world_matrix(e), v.size, v.probe_counts, e.id()});
  });
  world.each<ReflectionProbe>([&](Entity e, const ReflectionProbe& p) {
    view.reflection_probes.push_back({world.world_matrix(e), p, e.id()});
  });
  if (Entity post = first_with<PostProcessSettings>(world); !post.is_null())
    view.exposure = world.get<PostProcessSettings>(post).exposure;
  return view;
}

}  // namespace lg
