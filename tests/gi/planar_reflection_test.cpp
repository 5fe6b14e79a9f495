// gi.planar_reflection on lavapipe: a mirror floor under a glowing box, with no other light, so
// that what the mirror shows is known exactly: per pixel, the camera's ray reflected in the
// floor either meets the box (its emission) or the black sky. Also the coverage and a camera
// grazing the floor. (Without reflectors the node is bypassed: tests/compiler/examples_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <optional>
#include <string>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_file.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{160, 90};
const glm::vec3 kEmission(2.0f, 1.0f, 0.5f);
const glm::vec3 kBoxMin(-0.5f, 1.0f, -2.5f), kBoxMax(0.5f, 2.0f, -1.5f);

constexpr const char* kGraph = R"({ "format": "lumagraph/1", "name": "planar",
    "nodes": [ { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "planar", "type": "gi.planar_reflection" } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "planar.gbuffer" } ],
    "outputs": [ "planar.reflections" ] })";

// The mirror floor (8 m square at y = 0) and the box between kBoxMin and kBoxMax; `camera` is
// the camera entity's transform.
std::string world_text(const std::string& camera) {
  return R"({"format": "lumagraph-world/1", "materials": {
      "mirror": {"base_color": [1, 1, 1], "roughness": 0, "metalness": 1},
      "lamp": {"base_color": [0, 0, 0], "emissive": [2, 1, 0.5]}},
    "entities": [
      {"name": "floor", "shape": {"type": "quad", "size": [8, 8]}, "material": "mirror", "planar_reflector": true},
      {"name": "box", "shape": {"type": "box", "size": [1, 1, 1]}, "transform": {"position": [0, 1.5, -2]},
       "material": "lamp"},
      {"name": "camera", "transform": )" + camera + R"(, "camera": {"vertical_fov": 50}}]})";
}

std::unique_ptr<Renderer> render(const World& world) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;
  auto renderer = std::make_unique<Renderer>(options);
  Diagnostics d("planar-test.json");
  std::optional<Graph> graph = parse_graph_text(kGraph, d);
  if (!graph) throw std::runtime_error(d.to_string());
  renderer->set_graph(std::move(*graph));
  renderer->render(world, kFrame);
  auto messages = renderer->context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
  return renderer;
}

struct Ray {
  glm::vec3 origin, direction;
};

// The camera's ray through the point (x, y) of the frame, in pixels from the top left.
Ray camera_ray(const CameraView& camera, float x, float y) {
  const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
  const glm::vec2 ndc(2.0f * x / float(kFrame.width) - 1.0f, 2.0f * y / float(kFrame.height) - 1.0f);
  const glm::vec4 near = inverse * glm::vec4(ndc, 1.0f, 1.0f), far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
  return {camera.position, glm::normalize(glm::vec3(far) / far.w - glm::vec3(near) / near.w)};
}

bool hits_box(const Ray& r) {
  float t0 = 0.0f, t1 = 1e30f;
  for (int a = 0; a < 3; ++a) {
    const float inverse = 1.0f / r.direction[a];
    float near = (kBoxMin[a] - r.origin[a]) * inverse, far = (kBoxMax[a] - r.origin[a]) * inverse;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near), t1 = std::min(t1, far);
  }
  return t0 <= t1;
}

enum class Seen { box, sky, other };

// What the mirror shows along the ray, or `other` where it misses the floor.
Seen mirror_sees(const Ray& r) {
  if (r.direction.y >= 0.0f) return Seen::other;
  const float t = -r.origin.y / r.direction.y;
  const glm::vec3 p = r.origin + t * r.direction;
  if (std::abs(p.x) > 4.0f || std::abs(p.z) > 4.0f || hits_box(r)) return Seen::other;
  return hits_box({p, glm::vec3(r.direction.x, -r.direction.y, r.direction.z)}) ? Seen::box : Seen::sky;
}

TEST(PlanarReflection, MirrorFloorShowsTheBoxWhereItsReflectedRaysMeetIt) {
  const World world =
      parse_scene_file(world_text(R"({"position": [0, 1.2, 3], "look_at": [0, 0.3, -1]})"), "planar-world.json");
  auto renderer = render(world);
  const std::vector<float> rgba = renderer->executor().read_image("planar.reflections");
  const CameraView& camera = renderer->scene_view().camera;
  size_t box_pixels = 0, sky_pixels = 0;
  for (uint32_t y = 0; y < kFrame.height; ++y)
    for (uint32_t x = 0; x < kFrame.width; ++x) {
      const float* px = &rgba[(size_t(y) * kFrame.width + x) * 4];
      const glm::vec3 radiance(px[0], px[1], px[2]);
      const Seen seen = mirror_sees(camera_ray(camera, x + 0.5f, y + 0.5f));
      // The floor and only the floor is covered (no reflections input to pass through).
      ASSERT_EQ(px[3], seen == Seen::other ? 0.0f : 1.0f) << "pixel " << x << ", " << y;
      // Half-resolution views and bilinear reads blur an edge over two pixels: compared only
      // where the rays two pixels around see the same.
      bool uniform = seen != Seen::other;
      for (float dy : {-2.0f, 2.0f})
        for (float dx : {-2.0f, 2.0f}) uniform &= mirror_sees(camera_ray(camera, x + 0.5f + dx, y + 0.5f + dy)) == seen;
      if (!uniform) continue;
      if (seen == Seen::box) {
        // The lamp's emission exactly, but for half-float rounding (2^-11 relative).
        EXPECT_NEAR(glm::distance(radiance, kEmission), 0.0f, 2e-3f) << "pixel " << x << ", " << y;
        ++box_pixels;
      } else {
        EXPECT_EQ(radiance, glm::vec3(0.0f)) << "pixel " << x << ", " << y;
        ++sky_pixels;
      }
    }
  // The reflected box and the reflected sky both take a good part of the floor.
  EXPECT_GT(box_pixels, 300u);
  EXPECT_GT(sky_pixels, 1000u);
}

TEST(PlanarReflection, GrazingCameraStaysFinite) {
  const World world =
      parse_scene_file(world_text(R"({"position": [0, 0.02, 3.5], "look_at": [0, 0.02, -4]})"), "planar-world.json");
  auto renderer = render(world);
  size_t covered = 0;
  const std::vector<float> rgba = renderer->executor().read_image("planar.reflections");
  for (size_t i = 0; i < rgba.size(); ++i) ASSERT_TRUE(std::isfinite(rgba[i])) << "value " << i;
  for (size_t i = 3; i < rgba.size(); i += 4) covered += rgba[i] > 0.0f;
  EXPECT_GT(covered, 0u);  // the floor still reflects, at 89 degrees
}

}  // namespace
}  // namespace lg::test
