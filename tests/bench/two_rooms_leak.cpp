#include "tests/bench/two_rooms_leak.h"

#include <cmath>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/raytrace/camera_pixels.h"
#include "runtime/scene/make_scene_view.h"

namespace lg::bench {

RoomFloors two_rooms_floors(World world, uint32_t width, uint32_t height,
                            const std::function<std::vector<float>(const World&)>& irradiance) {
  auto floor_mean = [&](glm::vec3 eye, glm::vec3 at) {
    world.each<Camera, Transform>([&](Entity, Camera&, Transform& t) {
      t.position = eye;
      t.rotation = look_rotation(at - eye);
    });
    const std::vector<float> e = irradiance(world);
    // Which pixels see the floor: its top face is y = 0, facing up.
    const SceneView view = make_scene_view(world, float(width) / height);
    const PathScene scene(view, PathEnvironment::none());
    const PathTransport transport(scene, 1);
    const CameraPixels camera(view.camera, width, height);
    double sum = 0;
    size_t n = 0;
    for (uint32_t y = 0; y < height; ++y)
      for (uint32_t x = 0; x < width; ++x) {
        const auto s = transport.visible_surface(camera.eye(), camera.ray_direction(x, y), true);
        if (!s || s->normal.y < 0.9 || s->position.y > 0.05) continue;
        sum += e[4 * (size_t(y) * width + x) + 1], ++n;
      }
    return n ? sum / double(n) : std::nan("");
  };
  RoomFloors out;
  out.east = floor_mean({3.7f, 1.6f, 1.7f}, {0.3f, 0.0f, -1.0f});
  out.west = floor_mean({-3.7f, 1.6f, 1.7f}, {-0.3f, 0.0f, -1.0f});
  return out;
}

}  // namespace lg::bench
