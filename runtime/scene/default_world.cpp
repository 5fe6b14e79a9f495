#include "runtime/scene/default_world.h"

#include <glm/geometric.hpp>

#include "runtime/scene/mesh_generators.h"

namespace lg {
namespace {

Entity place(World& world, std::string name, glm::vec3 position, glm::quat rotation = glm::quat(1, 0, 0, 0),
             glm::vec3 scale = glm::vec3(1.0f)) {
  Entity e = world.create(std::move(name));
  world.add<Transform>(e, {position, rotation, scale, {}});
  return e;
}

void add_drawable(World& world, std::string name, int mesh, int material, glm::vec3 position,
                  glm::quat rotation = glm::quat(1, 0, 0, 0), glm::vec3 scale = glm::vec3(1.0f)) {
  Entity e = place(world, std::move(name), position, rotation, scale);
  world.add<MeshRenderer>(e, {mesh, material});
}

PbrMaterial material(std::string name, glm::vec3 base_color, float roughness, float metalness = 0.0f) {
  PbrMaterial m;
  m.name = std::move(name);
  m.base_color = glm::vec4(base_color, 1.0f);
  m.roughness = roughness;
  m.metalness = metalness;
  return m;
}

// The room spans x in [-5, 5], z in [-3, 3], walls 3 m high; the front (+Z) is open.
void add_room(World& world) {
  int floor = world.add_material(material("floor", {0.60f, 0.58f, 0.55f}, 0.8f));
  int wall = world.add_material(material("wall", {0.75f, 0.73f, 0.70f}, 0.95f));
  int floor_mesh = world.add_mesh(make_box({10.0f, 0.1f, 6.0f}));
  int back_mesh = world.add_mesh(make_box({10.0f, 3.0f, 0.1f}));
  int side_mesh = world.add_mesh(make_box({0.1f, 3.0f, 6.0f}));
  add_drawable(world, "floor", floor_mesh, floor, {0.0f, -0.05f, 0.0f});
  add_drawable(world, "back wall", back_mesh, wall, {0.0f, 1.5f, -3.05f});
  add_drawable(world, "left wall", side_mesh, wall, {-5.05f, 1.5f, 0.0f});
  add_drawable(world, "right wall", side_mesh, wall, {5.05f, 1.5f, 0.0f});
}

// Six spheres each: a red dielectric from roughness 0 to 1 at the back, a gold from
// metalness 0 to 1 (roughness 0.25) in front of it.
void add_sphere_rows(World& world) {
  int sphere = world.add_mesh(make_sphere(0.3f));
  constexpr int count = 6;
  for (int i = 0; i < count; ++i) {
    float t = float(i) / float(count - 1), x = -3.2f + 4.8f * t;
    std::string n = std::to_string(i);
    int rough = world.add_material(material("roughness " + n, {0.80f, 0.12f, 0.08f}, t));
    int metal = world.add_material(material("metalness " + n, {1.00f, 0.78f, 0.34f}, 0.25f, t));
    add_drawable(world, "rough sphere " + n, sphere, rough, {x, 0.3f, -1.8f});
    add_drawable(world, "metal sphere " + n, sphere, metal, {x, 0.3f, -0.6f});
  }
}

void add_lights_and_camera(World& world) {
  Entity sun = place(world, "sun", {0.0f, 0.0f, 0.0f}, look_rotation({-0.4f, -0.8f, -0.45f}));
  world.add<DirectionalLight>(sun, {{1.0f, 0.95f, 0.85f}, 8.0f, 0.00465f, true});

  Entity sky = world.create("sky");
  world.add<EnvironmentLight>(sky, {"", 1.0f});

  // About 1.8 W/m^2 at 1 m (pi L (r/d)^2): a warm glow on the bunny and the floor near it. It
  // and the strip cast no shadows, so the default frame needs no local shadow atlas (the
  // compiler's default scene summary says so too) and keeps its cost.
  Entity bulb = place(world, "sphere light", {1.5f, 0.9f, 1.0f});
  world.add<SphereLight>(bulb, {{1.0f, 0.7f, 0.4f}, 40.0f, 0.12f, false});

  // A cool strip along the top of the back wall, grazing it and lighting the sphere rows.
  Entity strip = place(world, "tube light", {0.0f, 2.5f, -2.6f});
  world.add<TubeLight>(strip, {{0.6f, 0.8f, 1.0f}, 25.0f, 2.0f, 0.04f, false});

  const glm::vec3 eye{0.0f, 1.5f, 5.2f}, target{0.0f, 0.55f, -1.0f};
  Entity camera = place(world, "camera", eye, look_rotation(target - eye));
  world.add<Camera>(camera, {glm::radians(42.0f), 0.05f, 0.0f, glm::length(target - eye)});
  world.add<PostProcessSettings>(camera, {0.0f});
  world.active_camera = camera;
}

}  // namespace

World default_world() {
  World world;
  world.name = "default";
  add_room(world);
  add_sphere_rows(world);
  int fur = world.add_material(material("bunny", {0.85f, 0.82f, 0.78f}, 0.6f));
  add_drawable(world, "bunny", world.add_mesh(make_bunny()), fur, {2.5f, 0.0f, 0.1f},
               glm::angleAxis(glm::radians(-30.0f), glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec3(1.8f));
  add_lights_and_camera(world);
  return world;
}

}  // namespace lg
