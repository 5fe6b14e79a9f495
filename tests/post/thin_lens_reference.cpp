#include "tests/post/thin_lens_reference.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <stdexcept>

#include "runtime/scene/camera_jitter.h"

namespace lg::test {
namespace {

constexpr double kGoldenAngle = 2.39996322972865332;

double focal_pixels(const Camera& camera, FrameSize frame) {
  return 0.5 * double(frame.height) / std::tan(0.5 * double(camera.vertical_fov));
}

Entity camera_entity(const World& world) {
  if (world.has<Camera>(world.active_camera)) return world.active_camera;
  Entity chosen;
  world.each<Camera>([&](Entity e, const Camera&) {
    if (chosen.is_null() || e.index < chosen.index) chosen = e;
  });
  if (chosen.is_null()) throw std::invalid_argument("thin-lens reference: the world has no camera");
  return chosen;
}

}  // namespace

std::vector<glm::vec2> aperture_samples(float diameter, uint32_t count) {
  std::vector<glm::vec2> points;
  for (uint32_t i = 0; i < count; ++i) {
    const double r = 0.5 * diameter * std::sqrt((i + 0.5) / count), a = i * kGoldenAngle;
    points.emplace_back(float(r * std::cos(a)), float(r * std::sin(a)));
  }
  return points;
}

// Clip y points down (runtime/scene/projection.h), so a camera moved up shifts the image up.
glm::vec2 focus_plane_jitter(glm::vec2 offset, const Camera& camera, FrameSize frame) {
  const double scale = focal_pixels(camera, frame) / camera.focus_distance;
  return {float(offset.x * scale), float(-offset.y * scale)};
}

double coc_radius_pixels(const Camera& camera, FrameSize frame, double depth) {
  return 0.5 * camera.aperture * focal_pixels(camera, frame) * std::abs(1.0 / camera.focus_distance - 1.0 / depth);
}

std::vector<float> thin_lens_reference(Renderer& renderer, World& world, FrameSize frame, uint32_t samples,
                                       std::string_view image) {
  const Entity entity = camera_entity(world);
  Transform& transform = world.get<Transform>(entity);
  if (!transform.parent.is_null()) throw std::invalid_argument("thin-lens reference: the camera has a parent");
  const Transform centre = transform;
  const Camera camera = world.get<Camera>(entity);
  std::vector<double> sum;
  const std::vector<glm::vec2> lens = aperture_samples(camera.aperture, samples);
  for (uint32_t i = 0; i < samples; ++i) {
    world.get<Transform>(entity).position = centre.position + centre.rotation * glm::vec3(lens[i], 0.0f);
    const glm::vec2 jitter = focus_plane_jitter(lens[i], camera, frame) + halton_jitter_pixels(i);
    renderer.render(world, frame, {.jitter = jitter});
    const std::vector<float> pixels = renderer.executor().read_image(image);
    sum.resize(pixels.size(), 0.0);
    for (size_t k = 0; k < pixels.size(); ++k) sum[k] += pixels[k];
  }
  world.get<Transform>(entity) = centre;
  std::vector<float> mean(sum.size());
  for (size_t k = 0; k < sum.size(); ++k) mean[k] = float(sum[k] / samples);
  return mean;
}

}  // namespace lg::test
